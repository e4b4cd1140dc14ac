// SPDX-License-Identifier: MIT
// `vroc sweep`: speed against accuracy, Erez-style (docs/harness.md). Per backend and frame step:
// accuracy = self-consistency error after re-anchored windows against the same backend at a tiny
// step (and the closed-form error for built-in check scenes), cost = wall time per simulated
// second; the Pareto front; the robustness limit; and model detail against a target error.
#pragma once

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "vroc/harness/commands/check_suite.h"
#include "vroc/harness/commands/detail_levels.h"
#include "vroc/harness/commands/sweep_curves.h"
#include "vroc/harness/documents/metrics_document.h"
#include "vroc/harness/pool/run_pool.h"
#include "vroc/harness/runs/backend_selection.h"

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

/// A frame step [s] as its rate: "1/60".
std::string frameStepName(double dt);

/// The default steps: 1/60, 1/120, ..., 1/960 s.
std::vector<double> defaultSweepSteps();

/// What a sweep's runs depend on (scene, backends, options, build): the plan RunPool hashes so that
/// --resume reuses only runs of the same sweep.
Json sweepPlan(const SweepScene& scene, const std::vector<SelectedBackend>& backends, const SweepOptions& options);

/// One (curve, frame step) run.
struct SweepStep {
    double dt = 0;                        ///< [s] frame step
    bool measured = false;                ///< false: a robustness-only step (larger than the swept ones)
    double cost = NAN;                    ///< [s wall per s simulated] (measured steps)
    double window_error = NAN;            ///< [m] mean over the re-anchored windows; NaN: none, or non-finite
    double closed_form_error = NAN;       ///< |measured - closed form| in the metric's units; NaN: none
    double step_p50_us = NAN;             ///< [µs] median step wall time
    bool robust = false;                  ///< completed without NaN, tunnelling, blow-up or collapse
    std::string failure;                  ///< why not robust
    std::string state_hash;               ///< of the last frame
    /// Empty, or why the run (or one of its windows) is not the engine's physics (run_validity.h):
    /// such a point is shown, marked, and never on the Pareto front.
    std::string not_valid;
};

/// One (curve, model detail level) run at the largest step.
struct SweepDetail {
    std::string level;                    ///< DetailLevel::name
    int faces = 0;                        ///< of the virtual bodies at this level
    double cost = NAN;                    ///< [s wall per s simulated]
    double window_error = NAN;            ///< [m] against the full-detail reference
    bool meets_target = false;            ///< window_error <= SweepOptions::target
    std::string state_hash;
};

struct SweepCurveResult {
    SweepCurve curve;                     ///< backend, settings and label
    std::vector<SweepStep> steps;         ///< robustness steps then swept steps, largest first
    std::optional<double> convergence_order;     ///< p of error ~ dt^p over the measured steps
    std::optional<double> robustness_limit_dt;   ///< [s] largest step from which every smaller one is robust
    std::vector<SweepDetail> details;     ///< in SweepOptions::details order
    std::optional<std::string> cheapest_meeting_target;   ///< detail level
};

/// A measured (curve, step) point of the speed-accuracy plane.
struct SweepPoint {
    std::size_t curve = 0;                ///< index into SweepResult::curves
    std::size_t step = 0;                 ///< index into that curve's steps
    bool on_pareto_front = false;
};

struct SweepResult {
    std::string source;                   ///< the scene as given (file or check:<id>)
    Scene scene;
    std::vector<SelectedBackend> backends;   ///< those that can represent the scene
    Json support;                         ///< per requested backend, as representableBackends gives it
    std::vector<double> dts;              ///< [s] swept steps, largest first
    std::vector<double> robustness_dts;   ///< [s] every step tried for the robustness limit, largest first
    double reference_dt = 0;              ///< [s]
    double duration = 0;                  ///< [s] of each run
    std::size_t windows = 0;              ///< re-anchored windows used
    double window = 0;                    ///< [s] their length
    std::optional<CheckMetric> closed_form;
    std::optional<double> target;         ///< [m]
    std::vector<std::string> vary;
    bool detail_sweep = false;            ///< model detail levels were swept
    std::vector<SweepCurveResult> curves;
    std::vector<SweepPoint> points;       ///< every measured step, curve by curve
    PoolExecution execution;

    const SweepStep& stepOf(const SweepPoint& p) const { return curves[p.curve].steps[p.step]; }
};

/// Runs the sweep over `pool` (reference runs first, then every step and detail run); only the
/// pool writes files (its finished runs). The metrics document is written by sweepDocument.
SweepResult runSweep(const SweepScene& scene, const std::vector<SelectedBackend>& backends, const SweepOptions& options, RunPool& pool);

}  // namespace vroc::harness
