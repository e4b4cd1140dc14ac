// SPDX-License-Identifier: MIT
// `vroc report DIR...`: rebuild or merge reports from metrics.json of earlier runs.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "command.h"
#include "vroc/harness/commands/report_merge.h"

namespace vroc::cli {
namespace {

struct ReportArgs {
    std::vector<std::string> dirs;
    std::string out_dir;
};

int report(const ReportArgs& a) {
    std::vector<std::filesystem::path> dirs(a.dirs.begin(), a.dirs.end());
    const std::filesystem::path out = !a.out_dir.empty() ? std::filesystem::path(a.out_dir)
                                      : dirs.size() == 1 ? dirs.front() : std::filesystem::path("runs/report-merged");
    const auto path = harness::rebuildReport(dirs, out);
    std::printf("vroc report: %s\n", std::filesystem::absolute(path).lexically_normal().string().c_str());
    return 0;
}

Action setupReport(CLI::App& sub, const Context&) {
    auto a = std::make_shared<ReportArgs>();
    sub.add_option("dirs", a->dirs, "Directories of earlier compare/check/sweep/ensemble runs (each holds metrics.json)")->required();
    sub.add_option("--out,-o", a->out_dir, "Where to write report.html (default: the directory itself, or runs/report-merged for several)");
    return [a] { return report(*a); };
}

}  // namespace

Command makeReportCommand() {
    return {"report", "Rebuild or merge report.html from metrics.json of earlier runs", &setupReport};
}

}  // namespace vroc::cli
