// SPDX-License-Identifier: MIT
#include "vroc/harness/documents/series_tools.h"

namespace vroc::harness {

std::vector<std::size_t> strideIndices(std::size_t count, std::size_t max_points) {
    std::vector<std::size_t> out;
    if (count == 0 || max_points == 0) return out;
    const std::size_t stride = (count + max_points - 1) / max_points;
    for (std::size_t i = 0; i < count; i += stride) out.push_back(i);
    if (out.back() != count - 1) {
        if (out.size() == max_points) out.back() = count - 1;
        else out.push_back(count - 1);
    }
    return out;
}

std::vector<double> pick(const std::vector<double>& values, const std::vector<std::size_t>& indices) {
    std::vector<double> out;
    out.reserve(indices.size());
    for (std::size_t i : indices) out.push_back(values[i]);
    return out;
}

}  // namespace vroc::harness
