// SPDX-License-Identifier: MIT
// `vroc check`: the analytic accuracy and stability suite (docs/harness.md).
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "command.h"
#include "vroc/core/recording/atomic_output.h"
#include "vroc/harness/check.h"
#include "vroc/harness/html_report.h"
#include "vroc/harness/output_dir.h"

namespace vroc::cli {
namespace {

struct CheckArgs {
    std::string backends;
    std::string out_dir;
    std::vector<std::string> assignments;
    harness::CheckOptions options;
    bool quiet = false;
};

int check(CheckArgs& a, const Context& context) {
    const auto backends = harness::selectBackends(a.backends, a.assignments);
    a.options.progress = !a.quiet;
    a.options.command_line = context.command_line;
    const auto out = a.out_dir.empty() ? harness::defaultOutputDir("check", a.options.long_set ? "long" : "default")
                                       : std::filesystem::path(a.out_dir);
    recording::prepareOutputDirectory(out);
    const harness::Json doc = harness::runCheckSuite(backends, a.options);
    harness::writeDocument(doc, out / "metrics.json");
    const auto report = harness::writeReport({doc}, out);
    std::fputs(harness::checkTableText(doc).c_str(), stdout);
    std::printf("vroc check: report %s\n", std::filesystem::absolute(report).lexically_normal().string().c_str());
    const int code = harness::checkExitCode(doc);
    if (code != 0)
        std::fprintf(stderr, "vroc check: %d check(s) required for native failed on native\n",
                     doc["results"]["required_failures_native"].get<int>());
    return code;
}

Action setup(CLI::App& sub, const Context& context) {
    auto a = std::make_shared<CheckArgs>();
    sub.add_option("--backends", a->backends, "Backends to check, comma-separated (default: all)");
    sub.add_option("--out,-o", a->out_dir, "Output directory (default runs/check-<set>-<time>/)");
    sub.add_flag("--long", a->options.long_set, "Also run the long set (intermediate-axis tumble, 10-box stack, rest time)");
    sub.add_option("--only", a->options.only, "Run only these scenario ids, repeatable")
        ->expected(1)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    sub.add_option("--set", a->assignments, "Backend setting key=value (key starts with the backend name), repeatable")
        ->expected(1)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    sub.add_flag("--quiet,-q", a->quiet, "No progress lines");
    sub.footer("Prints the check x backend table; writes metrics.json and report.html.\n"
               "Exit code 1 when a check required for native fails on the native backend.");
    return [a, context] { return check(*a, context); };
}

}  // namespace

Command makeCheckCommand() {
    return {"check", "Analytic accuracy and stability suite; exit 1 if native fails a required check", &setup};
}

}  // namespace vroc::cli
