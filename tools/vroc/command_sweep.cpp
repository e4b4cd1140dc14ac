// SPDX-License-Identifier: MIT
// `vroc sweep SCENE --backends ...`: speed against accuracy, Erez-style (docs/harness.md).
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "command.h"
#include "footing_options.h"
#include "frame_steps.h"
#include "run_pool_options.h"
#include "vroc/core/errors.h"
#include "vroc/core/recording/output_dir.h"
#include "vroc/harness/commands/sweep.h"
#include "vroc/harness/commands/sweep_curves.h"
#include "vroc/harness/documents/sweep_document.h"
#include "vroc/harness/pool/mpi_world.h"

namespace vroc::cli {
namespace {

struct SweepArgs {
    std::string scene;
    std::string backends;
    std::string out_dir;
    std::string dts;
    std::string details;
    std::optional<double> reference_dt;
    std::optional<double> target;
    std::vector<std::string> assignments;
    harness::SweepOptions options;
    PoolArgs pool;
    FootingArgs footing;
    bool quiet = false;
};

int sweep(SweepArgs& a, const Context& context) {
    const auto backends = footedBackends(a.footing, a.backends, a.assignments, false);
    announceFooting("sweep", backends, a.quiet);
    if (!a.dts.empty()) a.options.dts = parseFrameSteps(a.dts);
    if (!a.details.empty()) a.options.details = harness::parseDetailLevels(a.details);
    if (a.target && !(*a.target > 0)) throw InputError("--target: expected a positive error in metres");
    if (!(a.options.duration > 0)) throw InputError("--duration: expected a positive number of seconds");
    a.options.reference_dt = a.reference_dt;
    a.options.target = a.target;
    a.options.progress = !a.quiet;
    a.options.command_line = context.command_line;
    harness::sweepCurves(backends, a.options.vary);   // bad --vary fails before any file is written
    const harness::SweepScene scene = harness::loadSweepScene(a.scene);
    const auto out = a.out_dir.empty() ? recording::timestampedOutputDir({"sweep", scene.scene.name}) : std::filesystem::path(a.out_dir);
    harness::SweepResult result;
    const PooledResult r = runPooled(a.pool, out, !a.out_dir.empty(), harness::sweepPlan(scene, backends, a.options), "sweep",
                                     !a.quiet && context.stderr_is_terminal, [&](harness::RunPool& pool) {
                                         result = harness::runSweep(scene, backends, a.options, pool);
                                         return harness::sweepDocument(result, a.options.command_line);
                                     });
    if (!harness::mpi::isRoot()) return 0;
    for (const harness::SweepPoint& p : result.points) {
        if (!p.on_pareto_front) continue;
        const harness::SweepStep& s = result.stepOf(p);
        std::printf("vroc sweep: Pareto front: %s dt %.6g s, cost %.4g s/s, error %.3g m\n", result.curves[p.curve].curve.label.c_str(),
                    s.dt, s.cost, s.window_error);
    }
    std::printf("vroc sweep: report %s\n", r.report.string().c_str());
    return 0;
}

Action setupSweep(CLI::App& sub, const Context& context) {
    auto a = std::make_shared<SweepArgs>();
    sub.add_option("scene", a->scene, "Scene file, or check:<id> for a built-in check scene with a closed form")->required();
    sub.add_option("--backends", a->backends, "Backends, comma-separated (default: all)");
    sub.add_option("--out,-o", a->out_dir, "Output directory (default runs/sweep-<scene>-<time>/)");
    sub.add_option("--dt", a->dts, "Frame steps, comma-separated, e.g. 1/60,1/120,1/240 (default 1/60 .. 1/960, factor 2)");
    sub.add_option("--reference-dt", a->reference_dt, "Step of the self-consistency reference [s] (default smallest/8)");
    sub.add_option("--duration", a->options.duration, "Simulated time of each run [s] (default 2)");
    sub.add_option("--windows", a->options.windows, "Number of re-anchored windows (default 10)");
    sub.add_option("--window", a->options.window, "Window length [s] (default 0.1)");
    sub.add_option("--detail", a->details, "Model detail levels: full, fractions of hull vertices, sphere (e.g. full,0.5,0.25,sphere)");
    sub.add_option("--target", a->target, "Target window error [m]: name the cheapest detail level meeting it");
    sub.add_option("--set", a->assignments, "Backend setting key=value (key starts with the backend name), repeatable")
        ->expected(1)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    sub.add_option("--vary", a->options.vary, "Vary a backend setting, KEY=V1,V2,... (one curve per value), repeatable")
        ->expected(1)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    sub.add_flag("--quiet,-q", a->quiet, "No progress bar (it is drawn only on a terminal anyway)");
    addPoolOptions(sub, a->pool);
    addFootingOptions(sub, a->footing);
    sub.footer("Writes metrics.json and report.html (speed-accuracy chart with the Pareto front, robustness limit), and each\nfinished run to runs/ as it completes. Runs in parallel (--jobs) and over MPI ranks (mpirun -n R vroc sweep ...).");
    return [a, context] { return sweep(*a, context); };
}

}  // namespace

Command makeSweepCommand() {
    return {"sweep", "Speed vs accuracy over frame steps and model detail; Pareto front, robustness limit",
            &setupSweep};
}

}  // namespace vroc::cli
