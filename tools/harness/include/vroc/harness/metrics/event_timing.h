// SPDX-License-Identifier: MIT
// Event metrics (M18): impacts per body from the backend's collision events, and rest time from
// the trajectory (so a backend that reports events differently is still judged the same way).
#pragma once

#include <optional>
#include <vector>

#include "vroc/core/backend.h"
#include "vroc/core/scene.h"
#include "vroc/harness/runs/run_trace.h"

namespace vroc::harness {

/// [s] times of the impacts of `body`: its events, where events of the same pair closer than
/// `merge_window` [s] to the previous one count as one impact (several contact points).
std::vector<double> impactTimes(const std::vector<CollisionEvent>& events, int body, double merge_window);

/// Speeds below which a body is at rest.
struct RestThreshold {
    double linear = 0.01;    ///< [m/s]
    double angular = 0.1;    ///< [rad/s]
};

/// [s] first frame time from which every virtual body stays at rest until the end, or nothing.
std::optional<double> restTime(const Scene& scene, const RunTrace& trace, RestThreshold threshold = {});

}  // namespace vroc::harness
