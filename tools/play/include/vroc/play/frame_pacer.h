// SPDX-License-Identifier: MIT
// Real-time pacing of `vroc play --realtime`: frame i of dt is due at host_zero + (i + 1) dt on
// the loader's host clock (steady_clock, CLOCK_MONOTONIC: plugin_host.cpp), the clock every
// PoseSample::time_ns is on. The loop waits with sleep_until, never by spinning; a frame that ends
// after its deadline is counted as missed and the next one starts at once (the deadline grid stays
// fixed, so a loop that fell behind catches up instead of drifting).
#pragma once

#include <cstdint>
#include <vector>

namespace vroc::play {

/// Mean, median, 95th percentile (nearest rank) and maximum of a set of latencies [ms].
struct LatencySummary {
    int count = 0;
    double mean = 0, p50 = 0, p95 = 0, max = 0;   ///< [ms]
};
LatencySummary summariseLatencies(std::vector<double> ms);

class FramePacer {
public:
    /// `dt` [s] > 0; `host_zero_ns` the host time of simulation time 0 (the first frame's start).
    FramePacer(double dt, std::int64_t host_zero_ns);
    /// [ns] host time at which frame i is due to be done: host_zero + round((i + 1) dt 1e9).
    std::int64_t deadline(int frame) const;
    /// Records whether frame i was done (at host time done_ns) after its deadline, then sleeps
    /// until the deadline if it is still ahead. Returns true if the frame missed it.
    bool finishFrame(int frame, std::int64_t done_ns);
    int missed() const { return missed_; }
    /// [ms] the most any frame was done past its deadline (0 if none missed).
    double worstLateness() const { return worst_late_ms_; }

private:
    double dt_;
    std::int64_t host_zero_ns_;
    int missed_ = 0;
    double worst_late_ms_ = 0;
};

}  // namespace vroc::play
