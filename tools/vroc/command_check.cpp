// SPDX-License-Identifier: MIT
// `vroc check`: the analytic accuracy and stability suite (docs/harness.md).
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "command.h"
#include "footing_options.h"
#include "run_pool_options.h"
#include "vroc/core/errors.h"
#include "vroc/core/recording/output_dir.h"
#include "vroc/harness/commands/check.h"
#include "vroc/harness/commands/check_suite.h"
#include "vroc/harness/documents/check_document.h"
#include "vroc/harness/pool/mpi_world.h"

namespace vroc::cli {
namespace {

struct CheckArgs {
    std::string backends;
    std::string out_dir;
    std::string scenes_dir;   ///< --scenes-dir ("" : scenes/stress here, else beside the program)
    std::vector<std::string> assignments;
    harness::CheckOptions options;
    PoolArgs pool;
    FootingArgs footing;
    bool quiet = false;
};

std::filesystem::path programDir() {
    char buffer[4096];
    const ssize_t n = readlink("/proc/self/exe", buffer, sizeof buffer - 1);
    if (n <= 0) return {};
    buffer[n] = '\0';
    return std::filesystem::path(buffer).parent_path();
}

// The stress scenes: --scenes-dir as given, else scenes/stress under the current directory, else
// ../../scenes/stress beside the program (the source tree when run from build/bin).
std::filesystem::path stressScenesDir(const std::string& option) {
    namespace fs = std::filesystem;
    if (!option.empty()) {
        if (!fs::is_directory(option))
            throw InputError("stress scenes directory " + option + " not found (given with --scenes-dir)");
        return option;
    }
    const fs::path here = "scenes/stress";
    if (fs::is_directory(here)) return here;
    const fs::path exe = programDir();
    const fs::path beside = exe.empty() ? fs::path() : (exe / "../../scenes/stress").lexically_normal();
    if (!beside.empty() && fs::is_directory(beside)) return beside;
    throw InputError("stress scenes directory not found: " + fs::absolute(here).string() +
                     (beside.empty() ? "" : " nor " + beside.string()) + " (set it with --scenes-dir DIR)");
}

int check(CheckArgs& a, const Context& context) {
    const auto backends = footedBackends(a.footing, a.backends, a.assignments, true);
    a.options.progress = !a.quiet;
    a.options.command_line = context.command_line;
    const bool stress = a.options.stress || std::any_of(a.options.only.begin(), a.options.only.end(), harness::isStressScenarioId);
    if (stress) a.options.scenes_dir = stressScenesDir(a.scenes_dir);
    const std::string set = std::string(a.options.long_set ? "long" : "default") + (stress ? "-stress" : "");
    const auto out = a.out_dir.empty() ? recording::timestampedOutputDir({"check", set}) : std::filesystem::path(a.out_dir);
    harness::CheckSuiteResult result;
    const PooledResult r = runPooled(a.pool, out, !a.out_dir.empty(), harness::checkPlan(backends, a.options), "check",
                                     !a.quiet && context.stderr_is_terminal, [&](harness::RunPool& pool) {
                                         result = harness::runCheckSuite(backends, a.options, pool);
                                         return harness::checkDocument(result, a.options.command_line);
                                     });
    const int code = result.exitCode();
    if (!harness::mpi::isRoot()) return code;   // rank 0 prints
    std::fputs(harness::checkTableText(result).c_str(), stdout);
    std::printf("vroc check: report %s\n", r.report.string().c_str());
    if (code != 0)
        std::fprintf(stderr, "vroc check: %d check(s) required for native failed on native\n", result.required_failures_native);
    return code;
}

Action setupCheck(CLI::App& sub, const Context& context) {
    auto a = std::make_shared<CheckArgs>();
    sub.add_option("--backends", a->backends, "Backends to check, comma-separated (default: all)");
    sub.add_option("--out,-o", a->out_dir, "Output directory (default runs/check-<set>-<time>/)");
    sub.add_flag("--long", a->options.long_set, "Also run the long set (intermediate-axis tumble, 10-box stack, rest time)");
    sub.add_flag("--stress", a->options.stress,
                 "Add the stress section (issue 9 scenes of scenes/stress: pyramids, 1:10 stack, plank, SimBenchmark 666, bins)");
    sub.add_option("--scenes-dir", a->scenes_dir,
                   "Directory of the stress scenes (default scenes/stress here, else ../../scenes/stress beside the program)");
    sub.add_option("--only", a->options.only, "Run only these scenario ids (stress-<scene> ids imply --stress), repeatable")
        ->expected(1)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    sub.add_option("--set", a->assignments, "Backend setting key=value (key starts with the backend name), repeatable")
        ->expected(1)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    sub.add_flag("--quiet,-q", a->quiet, "No progress bar (it is drawn only on a terminal anyway)");
    addPoolOptions(sub, a->pool);
    addFootingOptions(sub, a->footing);
    sub.footer(
        "Prints the check x backend table; writes metrics.json and report.html.\n"
        "Stress rows are required for native (issue 22: a regression exits 1); rows marked info are reported, not "
        "judged.\n"
        "Exit code 1 when a check required for native fails on the native backend.");
    return [a, context] { return check(*a, context); };
}

}  // namespace

Command makeCheckCommand() {
    return {"check", "Analytic accuracy and stability suite; exit 1 if native fails a required check", &setupCheck};
}

}  // namespace vroc::cli
