// SPDX-License-Identifier: MIT
#include "vroc/harness/statistics/pareto.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace vroc::harness {

std::vector<std::size_t> paretoFront(const std::vector<CostError>& points) {
    std::vector<std::size_t> order(points.size());
    std::iota(order.begin(), order.end(), 0);
    std::erase_if(order, [&](std::size_t i) { return !std::isfinite(points[i].cost) || !std::isfinite(points[i].error); });
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return points[a].cost != points[b].cost ? points[a].cost < points[b].cost : points[a].error < points[b].error;
    });
    // Sweep by increasing cost: a point is on the front iff its error beats every cheaper point.
    std::vector<std::size_t> front;
    double best = INFINITY;
    for (std::size_t i : order) {
        if (points[i].error < best) {
            front.push_back(i);
            best = points[i].error;
        }
    }
    return front;
}

std::optional<double> convergenceOrder(const std::vector<double>& dt, const std::vector<double>& error) {
    double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t i = 0; i < dt.size() && i < error.size(); ++i) {
        if (!(dt[i] > 0 && error[i] > 0) || !std::isfinite(dt[i]) || !std::isfinite(error[i])) continue;
        const double x = std::log(dt[i]), y = std::log(error[i]);
        n += 1; sx += x; sy += y; sxx += x * x; sxy += x * y;
    }
    const double denom = n * sxx - sx * sx;
    if (n < 2 || denom <= 0) return std::nullopt;
    return (n * sxy - sx * sy) / denom;
}

}  // namespace vroc::harness
