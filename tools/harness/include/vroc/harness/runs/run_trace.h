// SPDX-License-Identifier: MIT
// What one backend did on one scene, held in memory: the states of every body at every frame,
// the collision events, the wall time of every step and the invariants at every frame.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "vroc/core/backend.h"
#include "vroc/core/frame_loop.h"
#include "vroc/core/scene.h"
#include "vroc/core/settings.h"
#include "vroc/harness/metrics/invariants.h"

namespace vroc::harness {

struct RunTrace {
    std::string backend;                          ///< registry name
    double frame_dt = 0;                          ///< [s]
    std::vector<double> times;                    ///< [s] backend time at each frame; times[0] = start
    std::vector<std::vector<BodyState>> states;   ///< [frame][scene body]; frame 0 = initial state
    std::vector<Invariants> invariants;           ///< [frame] of the virtual bodies
    std::vector<CollisionEvent> events;           ///< every event, in time order
    std::vector<double> step_wall_s;              ///< [s] wall time of each stepFrame call
    WarningCounts warnings;                       ///< at the end
    Statistics statistics;                        ///< at the end
    bool finite = true;                           ///< false if any reported state was not finite

    std::size_t frames() const { return times.size(); }
    double wallTotal() const;                     ///< [s] sum of step_wall_s
    double simulatedTime() const { return times.empty() ? 0 : times.back() - times.front(); }
};

struct RunOptions {
    double frame_dt = 0;        ///< [s] > 0
    std::int64_t frames = 0;    ///< frames to step (>= 0; frameCount for a duration)
    /// If set: every virtual body starts from these states (indexed like Scene::bodies), applied
    /// through setBodyStates (core/body_states.h) on the fresh backend (re-anchoring, twin perturbation).
    std::optional<std::vector<BodyState>> initial_states;
    bool record_states = true;  ///< false keeps only the first and last frames (cost runs)
    std::int64_t record_every = 1;   ///< keep frames f with f % record_every == 0 (and the last)
    /// Called every frame with (frames done, total); may be empty.
    std::function<void(std::int64_t, std::int64_t)> progress;
};

/// Creates the backend from the scene and settings, steps it and records everything.
/// Throws what BackendInfo::create throws (InputError for settings the scene cannot honour).
RunTrace runBackend(const BackendInfo& backend, const Scene& scene, const Settings& settings,
                    const RunOptions& options);

/// The scene's initial states, indexed like Scene::bodies.
std::vector<BodyState> initialStates(const Scene& scene);


}  // namespace vroc::harness
