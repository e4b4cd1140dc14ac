// SPDX-License-Identifier: MIT
// Summary statistics of per-step wall times and other samples.
#pragma once

#include <vector>

namespace vroc::harness {

/// Nearest-rank percentile (p in [0, 100]) of the samples; 0 for an empty input.
double percentile(std::vector<double> samples, double p);

struct TimingSummary {
    double p50_us = 0, p90_us = 0, p99_us = 0, mean_us = 0, max_us = 0;   ///< [µs] per step
    double real_time_factor = 0;   ///< simulated time / wall time of the steps [-]
    double wall_per_sim_s = 0;     ///< [s wall per s simulated]
};

/// From per-step wall times [s] and the simulated time they covered [s].
TimingSummary summarizeTiming(const std::vector<double>& step_wall_s, double simulated_s);

struct Histogram {
    std::vector<double> centers;   ///< bin centres
    std::vector<double> counts;    ///< samples per bin
};

/// `bins` equal bins over [min, max] of the samples (one bin if all equal; empty if no samples).
Histogram histogram(const std::vector<double>& samples, int bins);

}  // namespace vroc::harness
