// SPDX-License-Identifier: MIT
// `vroc compare SCENE --backends a,b`: one scene on several backends (docs/harness.md).
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "command.h"
#include "footing_options.h"
#include "report_view.h"
#include "run_pool_options.h"
#include "vroc/core/errors.h"
#include "vroc/core/recording/output_dir.h"
#include "vroc/core/scene_loader.h"
#include "vroc/harness/commands/compare.h"
#include "vroc/harness/documents/compare_document.h"
#include "vroc/harness/pool/mpi_world.h"

namespace vroc::cli {
namespace {

struct CompareArgs {
    std::string scene_file;
    std::string backends;
    std::string out_dir;
    std::vector<std::string> assignments;
    harness::CompareOptions options;
    std::optional<double> dt;
    PoolArgs pool;
    FootingArgs footing;
    bool quiet = false;
    bool no_view = false;
};

int compare(CompareArgs& a, const Context& context) {
    if (!(a.options.duration > 0)) throw InputError("--duration: expected a positive number of seconds");
    if (a.dt && !(*a.dt > 0)) throw InputError("--dt: expected a positive number of seconds");
    if (!(a.options.window > 0) || a.options.windows < 1) throw InputError("--window/--windows: expected positive values");
    const auto backends = footedBackends(a.footing, a.backends, a.assignments, true);
    announceFooting("compare", backends, a.quiet);
    const Scene scene = loadScene(a.scene_file);
    a.options.frame_dt = a.dt;
    a.options.progress = !a.quiet;
    a.options.command_line = context.command_line;
    const auto out = a.out_dir.empty() ? recording::timestampedOutputDir({"compare", scene.name}) : std::filesystem::path(a.out_dir);
    const PooledResult r = runPooled(a.pool, out, !a.out_dir.empty(), harness::comparePlan(scene, backends, a.options), "compare",
                                     !a.quiet && context.stderr_is_terminal, [&](harness::RunPool& pool) {
                                         return harness::compareDocument(harness::compareScene(scene, backends, a.options, out, pool),
                                                                         a.options.command_line);
                                     });
    if (!harness::mpi::isRoot()) return 0;
    if (!a.no_view && a.options.write_csv) writeReportView(out, "compare", a.quiet);
    std::printf("vroc compare: report %s\n", r.report.string().c_str());
    return 0;
}

Action setupCompare(CLI::App& sub, const Context& context) {
    auto a = std::make_shared<CompareArgs>();
    sub.add_option("scene", a->scene_file, "Scene file (vroc-scene/1 JSON)")->required();
    sub.add_option("--backends", a->backends, "Backends to compare, comma-separated; the first is the reference (default: all)");
    sub.add_option("--out,-o", a->out_dir, "Output directory (default runs/compare-<scene>-<time>/)");
    sub.add_option("--duration", a->options.duration, "Simulated time [s] (default 5)");
    sub.add_option("--dt", a->dt, "Frame step [s] (default: the scene's frame_dt)");
    sub.add_option("--windows", a->options.windows, "Number of re-anchored windows K (default 10)");
    sub.add_option("--window", a->options.window, "Length of each re-anchored window [s] (default 0.25)");
    sub.add_option("--set", a->assignments, "Backend setting key=value (key starts with the backend name), repeatable")
        ->expected(1)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    sub.add_flag("--quiet,-q", a->quiet, "No progress bar (it is drawn only on a terminal anyway)");
    addPoolOptions(sub, a->pool);
    addFootingOptions(sub, a->footing);
    sub.add_flag("--no-view", a->no_view, "Do not write view.html, the 3D replay next to the report (docs/viewer.md)");
    sub.footer("Writes metrics.json, <backend>/{trajectory,events,step_times}.csv and report.html.");
    return [a, context] { return compare(*a, context); };
}

}  // namespace

Command makeCompareCommand() {
    return {"compare", "Run a scene on several backends; divergence, events, invariants, timings, report.html",
            &setupCompare};
}

}  // namespace vroc::cli
