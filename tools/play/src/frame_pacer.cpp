// SPDX-License-Identifier: MIT
#include "vroc/play/frame_pacer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <thread>

namespace vroc::play {

LatencySummary summariseLatencies(std::vector<double> ms) {
    LatencySummary s;
    if (ms.empty()) return s;
    std::sort(ms.begin(), ms.end());
    const auto rank = [&](double p) {   // nearest rank: the smallest value with >= p % at or below it
        const auto k = static_cast<std::size_t>(std::ceil(p / 100.0 * static_cast<double>(ms.size())));
        return ms[std::clamp<std::size_t>(k, 1, ms.size()) - 1];
    };
    s.count = static_cast<int>(ms.size());
    s.mean = std::accumulate(ms.begin(), ms.end(), 0.0) / static_cast<double>(ms.size());
    s.p50 = rank(50);
    s.p95 = rank(95);
    s.max = ms.back();
    return s;
}

FramePacer::FramePacer(double dt, std::int64_t host_zero_ns) : dt_(dt), host_zero_ns_(host_zero_ns) {
    if (!(dt > 0.0) || !std::isfinite(dt)) throw std::invalid_argument("FramePacer: dt must be positive");
}

std::int64_t FramePacer::deadline(int frame) const {
    return host_zero_ns_ + static_cast<std::int64_t>(std::llround((frame + 1) * dt_ * 1e9));
}

bool FramePacer::finishFrame(int frame, std::int64_t done_ns) {
    const std::int64_t due = deadline(frame);
    if (done_ns > due) {
        ++missed_;
        worst_late_ms_ = std::max(worst_late_ms_, static_cast<double>(done_ns - due) * 1e-6);
        return true;
    }
    // The host clock is steady_clock's count since its epoch, so the deadline is a steady_clock point.
    std::this_thread::sleep_until(std::chrono::steady_clock::time_point(std::chrono::nanoseconds(due)));
    return false;
}

}  // namespace vroc::play
