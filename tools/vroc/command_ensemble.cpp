// SPDX-License-Identifier: MIT
// `vroc ensemble SCENE --backends a,b --members N --perturb positions=1e-6`: the comparison that
// survives chaos (docs/harness.md, "Ensembles").
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "command.h"
#include "footing_options.h"
#include "frame_steps.h"
#include "report_view.h"
#include "run_pool_options.h"
#include "vroc/core/errors.h"
#include "vroc/core/recording/output_dir.h"
#include "vroc/core/scene_loader.h"
#include "vroc/harness/commands/ensemble.h"
#include "vroc/harness/documents/ensemble_document.h"
#include "vroc/harness/pool/mpi_world.h"

namespace vroc::cli {
namespace {

struct EnsembleArgs {
    std::string scene;
    std::string backends;
    std::string out_dir;
    std::string perturb;
    std::string dt;
    std::vector<std::string> assignments;
    harness::EnsembleOptions options;
    PoolArgs pool;
    FootingArgs footing;
    bool quiet = false;
    bool no_view = false;
};

int ensemble(EnsembleArgs& a, const Context& context) {
    const auto backends = footedBackends(a.footing, a.backends, a.assignments, false);
    announceFooting("ensemble", backends, a.quiet);
    if (!a.perturb.empty()) a.options.perturb = harness::parsePerturbation(a.perturb);
    if (!a.dt.empty()) a.options.frame_dt = parseFrameStep(a.dt);
    if (a.options.permutations != 0 && a.options.permutations < 99)
        throw InputError("--permutations: expected at least 99 (or 0: enough for the number of tests)");
    if (!(a.options.alpha > 0 && a.options.alpha < 1)) throw InputError("--alpha: expected a level in (0, 1)");
    // Checked before any folder is made, so bad input leaves nothing behind.
    if (a.options.members < 2) throw InputError("--members: expected at least 2 members per backend");
    if (!(a.options.duration > 0)) throw InputError("--duration: expected a positive number of seconds");
    if (backends.size() < 2) throw InputError("vroc ensemble compares backends: give at least two with --backends");
    a.options.source = a.scene;
    a.options.command_line = context.command_line;
    const Scene scene = loadScene(a.scene);
    const auto out = a.out_dir.empty() ? recording::timestampedOutputDir({"ensemble", scene.name}) : std::filesystem::path(a.out_dir);
    harness::EnsembleResult result;
    const PooledResult r = runPooled(a.pool, out, !a.out_dir.empty(), harness::ensemblePlan(scene, backends, a.options), "ensemble",
                                     !a.quiet && context.stderr_is_terminal, [&](harness::RunPool& pool) {
                                         result = harness::runEnsemble(scene, backends, a.options, pool);
                                         return harness::ensembleDocument(result);
                                     });
    if (!harness::mpi::isRoot()) return 0;
    std::fputs(harness::ensembleVerdictText(result).c_str(), stdout);
    if (!a.no_view) writeReportView(out, "ensemble", a.quiet);
    std::printf("vroc ensemble: report %s\n", r.report.string().c_str());
    return 0;
}

Action setupEnsemble(CLI::App& sub, const Context& context) {
    auto a = std::make_shared<EnsembleArgs>();
    sub.add_option("scene", a->scene, "Scene file")->required();
    sub.add_option("--backends", a->backends, "Backends, comma-separated, at least two (default: all)");
    sub.add_option("--out,-o", a->out_dir, "Output directory (default runs/ensemble-<scene>-<time>/)");
    sub.add_option("--members,-n", a->options.members, "Perturbed runs per backend (default 32)");
    sub.add_option("--perturb", a->perturb,
                   "Standard deviations of the initial-state noise: positions=M,velocities=M/S,orientations=RAD,angular=RAD/S "
                   "(default positions=1e-6)");
    sub.add_option("--duration", a->options.duration, "Simulated time of each member [s] (default 4)");
    sub.add_option("--dt", a->dt, "Frame step [s] (default 1/60)");
    sub.add_option("--seed", a->options.seed, "Seed of the perturbations and permutations (default 1)");
    sub.add_option("--permutations", a->options.permutations, "Permutations per test (default 0: max(999, 2 x tests / alpha), so each test can pass Holm's correction)");
    sub.add_option("--alpha", a->options.alpha, "Family-wise significance level, Holm-adjusted (default 0.05)");
    sub.add_option("--set", a->assignments, "Backend setting key=value (key starts with the backend name), repeatable")
        ->expected(1)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    sub.add_flag("--quiet,-q", a->quiet, "No progress bar");
    addPoolOptions(sub, a->pool);
    addFootingOptions(sub, a->footing);
    sub.add_flag("--no-view", a->no_view, "Do not write view.html, the 3D replay next to the report (docs/viewer.md)");
    sub.footer(
        "Prints, per backend pair, the observables that distinguish them (test and effect above the resolution\n"
        "floor), those within resolution or not reached, and any dropped members; writes metrics.json, report.html\n"
        "(led by a digest of pairs x observables coloured by effect) and each finished member to runs/.\n"
        "Runs in parallel (--jobs) and over MPI ranks (mpirun -n R vroc ensemble ...).");
    return [a, context] { return ensemble(*a, context); };
}

}  // namespace

Command makeEnsembleCommand() {
    return {"ensemble", "Perturbed ensembles per backend; which observables distinguish the backends (survives chaos)",
            &setupEnsemble};
}

}  // namespace vroc::cli
