// SPDX-License-Identifier: MIT
// Many simulations from a batch of initial states on several backends, on the harness's run pool
// (worker processes; the same bits for any number of jobs), as `vroc.rollout` presents them.
// Free of Python: the bindings hand in and take out flat arrays.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "vroc/core/backend.h"

namespace vroc::python {

struct RolloutRequest {
    const Scene* scene = nullptr;                 ///< not owned
    std::string backends;                         ///< "a,b" (harness::selectBackends)
    std::vector<std::string> assignments;         ///< "backend.key=value", routed by prefix
    std::vector<std::vector<BodyState>> initial;  ///< [member][scene body]
    std::int64_t frames = 0;                      ///< T >= 1
    double frame_dt = 0;                          ///< [s] <= 0: the scene's
    int jobs = 1;                                 ///< worker processes (1: in this process)
};

struct RolloutMember {
    std::vector<CollisionEvent> events;
    WarningCounts warnings;
    std::string state_hash;                       ///< of the last frame
};

struct RolloutResult {
    std::vector<std::string> backends;
    /// [backend][member][frame 1..T][body][13], flat, C order.
    std::vector<double> states;
    std::vector<std::vector<RolloutMember>> members;   ///< [backend][member]
    double wall_s = 0;                                 ///< [s] of the whole rollout
};

/// Throws InputError for bad backends, settings or sizes; RunError naming the runs that failed.
RolloutResult runRollout(const RolloutRequest& request);

}  // namespace vroc::python
