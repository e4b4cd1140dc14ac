// SPDX-License-Identifier: MIT
// Stepping a backend frame by frame: the one loop behind `vroc run` (recording/run_recorder.h) and
// every harness run (harness/run_trace.h), and the one rule for how many frames cover a duration.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "vroc/core/backend.h"

namespace vroc {

/// Frames of `dt` [s] that cover `duration` [s]: n = duration / dt rounded to the nearest integer
/// when it is within 1e-9 n of it (floating noise: 5 s at 1/60 s is 300 frames, 0.3 s at 0.1 s is
/// 3), else rounded up (1 s at 0.3 s is 4: the frames cover the duration); at least 1. Throws
/// InputError unless both are finite and positive and the count is at most 1e9.
std::int64_t frameCount(double duration, double dt);

struct FrameHooks {
    /// Before each frame's stepFrame, with the backend and the frame's start time [s]. May be empty.
    std::function<void(Backend&, double)> before_frame;
    /// After each frame, with its number (1 for the first), the wall time of its stepFrame call [s]
    /// and the collision events it took (Backend::takeEvents). Returning false stops the loop.
    /// May be empty.
    std::function<bool(std::int64_t frame, double step_wall_s, std::vector<CollisionEvent>& events)> after_frame;
};

/// Steps `backend` by `frames` frames of `dt` [s], calling the hooks around each. Returns the
/// frames stepped: `frames`, or fewer when after_frame stopped the loop.
std::int64_t stepFrames(Backend& backend, std::int64_t frames, double dt, const FrameHooks& hooks);

}  // namespace vroc
