// SPDX-License-Identifier: MIT
// Speed-accuracy helpers: the Pareto front of (cost, error) points and the convergence order.
#pragma once

#include <optional>
#include <vector>

namespace vroc::harness {

struct CostError {
    double cost = 0;    ///< [s wall per s simulated]
    double error = 0;   ///< [m] or the metric's unit
};

/// Indices of the points no other point beats in both cost and error (ties kept once), by cost.
/// Points with a non-finite coordinate are never on the front.
std::vector<std::size_t> paretoFront(const std::vector<CostError>& points);

/// Least-squares slope of ln(error) against ln(dt) over points with both positive and finite.
std::optional<double> convergenceOrder(const std::vector<double>& dt, const std::vector<double>& error);

}  // namespace vroc::harness
