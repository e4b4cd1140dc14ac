// SPDX-License-Identifier: MIT
// `vroc sweep`: speed against accuracy, Erez-style (docs/harness.md). Per backend and frame step:
// accuracy = self-consistency error after re-anchored windows against the same backend at a tiny
// step (and the closed-form error for built-in check scenes), cost = wall time per simulated
// second; the Pareto front; the robustness limit; and model detail against a target error.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "vroc/harness/backend_selection.h"
#include "vroc/harness/check_suite.h"
#include "vroc/harness/detail_levels.h"
#include "vroc/harness/metrics_document.h"
#include "vroc/harness/run_pool.h"

namespace vroc::harness {

struct SweepOptions {
    std::vector<double> dts;            ///< [s] frame steps; default 1/60 .. 1/960, factor 2
    std::optional<double> reference_dt; ///< [s] default: smallest step / 8
    double duration = 2.0;              ///< [s] of each run
    int windows = 10;                   ///< K re-anchored windows
    double window = 0.1;                ///< [s] Δ (rounded to a multiple of the largest step)
    std::vector<std::string> vary;      ///< `--vary KEY=V1,V2,...`: one curve per value (sweep_curves.h)
    std::vector<DetailLevel> details;   ///< empty: no detail sweep
    std::optional<double> target;       ///< [m] target window error for --detail
    int robustness_extra = 2;           ///< also try 2x, 4x, ... the largest step for the limit
    bool progress = true;
    std::string command_line;
};

/// The scene to sweep: a file, or "check:<id>" for a built-in check scene (with a closed form).
struct SweepScene {
    Scene scene;
    std::optional<CheckMetric> closed_form;   ///< first metric of the check scenario
    std::string source;                        ///< as given
};

/// Loads a scene file or builds a check scenario; throws InputError.
SweepScene loadSweepScene(const std::string& source);

/// The default steps: 1/60, 1/120, ..., 1/960 s.
std::vector<double> defaultSweepSteps();

/// What a sweep's runs depend on (scene, backends, options, build): the plan RunPool hashes so that
/// --resume reuses only runs of the same sweep.
Json sweepPlan(const SweepScene& scene, const std::vector<SelectedBackend>& backends, const SweepOptions& options);

/// Runs the sweep over `pool` (reference runs first, then every step and detail run) and returns
/// the metrics document; only the pool writes files (its finished runs).
Json runSweep(const SweepScene& scene, const std::vector<SelectedBackend>& backends, const SweepOptions& options, RunPool& pool);

}  // namespace vroc::harness
