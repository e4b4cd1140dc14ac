// SPDX-License-Identifier: MIT
#include "vroc/harness/statistics/timing_stats.h"

#include <algorithm>
#include <cmath>

namespace vroc::harness {

double percentile(std::vector<double> samples, double p) {
    if (samples.empty()) return 0;
    std::sort(samples.begin(), samples.end());
    // Nearest rank: the smallest value with at least p% of the samples at or below it.
    const double rank = std::ceil(p / 100.0 * static_cast<double>(samples.size()));
    const std::size_t index = static_cast<std::size_t>(std::clamp(rank, 1.0, static_cast<double>(samples.size()))) - 1;
    return samples[index];
}

TimingSummary summarizeTiming(const std::vector<double>& step_wall_s, double simulated_s) {
    TimingSummary t;
    if (step_wall_s.empty()) return t;
    double sum = 0, mx = 0;
    for (double s : step_wall_s) {
        sum += s;
        mx = std::max(mx, s);
    }
    t.p50_us = percentile(step_wall_s, 50) * 1e6;
    t.p90_us = percentile(step_wall_s, 90) * 1e6;
    t.p99_us = percentile(step_wall_s, 99) * 1e6;
    t.mean_us = sum / static_cast<double>(step_wall_s.size()) * 1e6;
    t.max_us = mx * 1e6;
    t.real_time_factor = sum > 0 ? simulated_s / sum : 0;
    t.wall_per_sim_s = simulated_s > 0 ? sum / simulated_s : 0;
    return t;
}

Histogram histogram(const std::vector<double>& samples, int bins) {
    Histogram h;
    if (samples.empty() || bins < 1) return h;
    const auto [lo_it, hi_it] = std::minmax_element(samples.begin(), samples.end());
    const double lo = *lo_it, hi = *hi_it;
    if (hi <= lo) {
        h.centers = {lo};
        h.counts = {static_cast<double>(samples.size())};
        return h;
    }
    const double width = (hi - lo) / bins;
    h.centers.resize(static_cast<std::size_t>(bins));
    h.counts.assign(static_cast<std::size_t>(bins), 0.0);
    for (int i = 0; i < bins; ++i) h.centers[static_cast<std::size_t>(i)] = lo + (i + 0.5) * width;
    for (double s : samples) {
        int i = static_cast<int>((s - lo) / width);
        h.counts[static_cast<std::size_t>(std::clamp(i, 0, bins - 1))] += 1;
    }
    return h;
}

}  // namespace vroc::harness
