// SPDX-License-Identifier: MIT
#include "vroc/core/frame_loop.h"

#include <charconv>
#include <chrono>
#include <cmath>
#include <string>

#include "vroc/core/errors.h"

namespace vroc {
namespace {

// Shortest text that reads back as the same double (messages, not files).
std::string number(double value) {
    char buf[32];
    auto result = std::to_chars(buf, buf + sizeof buf, value);
    return std::string(buf, result.ptr);
}

}  // namespace

std::int64_t frameCount(double duration, double dt) {
    if (!std::isfinite(dt) || dt <= 0)
        throw InputError("frame dt must be a finite positive number of seconds (got " + number(dt) + ")");
    if (!std::isfinite(duration) || duration <= 0)
        throw InputError("duration must be a finite positive number of seconds (got " + number(duration) + ")");
    const double ratio = duration / dt;
    if (ratio > 1e9)
        throw InputError("duration / dt = " + number(ratio) + " frames; at most 1e9 are allowed");
    const double nearest = std::round(ratio);
    const double frames = std::abs(ratio - nearest) <= 1e-9 * nearest ? nearest : std::ceil(ratio);
    return std::max<std::int64_t>(1, static_cast<std::int64_t>(frames));
}

std::int64_t stepFrames(Backend& backend, std::int64_t frames, double dt, const FrameHooks& hooks) {
    using Clock = std::chrono::steady_clock;
    for (std::int64_t frame = 1; frame <= frames; ++frame) {
        if (hooks.before_frame) hooks.before_frame(backend, backend.time());
        const auto start = Clock::now();
        backend.stepFrame(dt);
        const double wall = std::chrono::duration<double>(Clock::now() - start).count();
        std::vector<CollisionEvent> events = backend.takeEvents();
        if (hooks.after_frame && !hooks.after_frame(frame, wall, events)) return frame;
    }
    return frames;
}

}  // namespace vroc
