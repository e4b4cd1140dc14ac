// SPDX-License-Identifier: MIT
// Trajectory divergence between two runs of the same scene at the same frame step, and the
// numbers that survive chaos: twin spread (noise floor), predictability horizon and FTLE.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "vroc/core/backend.h"
#include "vroc/core/scene.h"
#include "vroc/harness/runs/run_trace.h"

namespace vroc::harness {

/// [m] largest distance between corresponding virtual-body origins of two states.
double maxPositionError(const Scene& scene, std::span<const BodyState> a, std::span<const BodyState> b);
/// [rad] largest rotation angle between corresponding virtual-body orientations (q and -q equal).
double maxAngleError(const Scene& scene, std::span<const BodyState> a, std::span<const BodyState> b);

struct Divergence {
    std::vector<double> t;          ///< [s] frame times (common frames only)
    std::vector<double> distance;   ///< [m] maxPositionError per frame
    std::vector<double> per_body_max;   ///< [m] per virtual body (scene order): max over frames
};

/// Frame-by-frame divergence of two traces (compared up to the shorter one).
Divergence divergence(const Scene& scene, const RunTrace& a, const RunTrace& b);

/// [s] first time the series exceeds `delta`, or nothing if it never does.
std::optional<double> horizon(std::span<const double> t, std::span<const double> spread, double delta);

/// [1/s] finite-time Lyapunov exponent: least-squares slope of ln(spread) against t over the
/// samples with lo < spread < hi; nothing if fewer than 3 such samples.
std::optional<double> ftle(std::span<const double> t, std::span<const double> spread, double lo, double hi);

struct Significance {
    std::optional<double> first_time;   ///< [s] first frame where d > both noise floors
    double fraction = 0;                ///< share of frames where it does [-]
};
/// Cross-backend divergence counts only where it exceeds each backend's own twin spread.
Significance significantDivergence(std::span<const double> d, std::span<const double> floor_a,
                                   std::span<const double> floor_b, std::span<const double> t);

}  // namespace vroc::harness
