// SPDX-License-Identifier: MIT
// Small helpers that turn traces into chart series.
#pragma once

#include <cstddef>
#include <vector>

namespace vroc::harness {

/// Every k-th index so that at most `max_points` remain (the last index always kept).
std::vector<std::size_t> strideIndices(std::size_t count, std::size_t max_points);

/// The values at those indices.
std::vector<double> pick(const std::vector<double>& values, const std::vector<std::size_t>& indices);

}  // namespace vroc::harness
