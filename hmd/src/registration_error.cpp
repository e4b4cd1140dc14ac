// SPDX-License-Identifier: MIT
#include "vroc/hmd/registration_error.h"

#include <algorithm>
#include <cmath>

#include "vroc/core/rotation_vector.h"

namespace vroc::hmd {

double registrationError(const Pose& true_eye, const Pose& drawn_eye, const Vec3& world_point) {
    return angleBetween(true_eye.applyInverse(world_point), drawn_eye.applyInverse(world_point));
}

double ErrorStatistics::mean() const {
    if (values_.empty()) return 0.0;
    double sum = 0.0;
    for (double v : values_) sum += v;
    return sum / static_cast<double>(values_.size());
}

double ErrorStatistics::rms() const {
    if (values_.empty()) return 0.0;
    double sum = 0.0;
    for (double v : values_) sum += v * v;
    return std::sqrt(sum / static_cast<double>(values_.size()));
}

double ErrorStatistics::max() const {
    return values_.empty() ? 0.0 : *std::max_element(values_.begin(), values_.end());
}

double ErrorStatistics::percentile(double p) const {
    if (values_.empty()) return 0.0;
    std::vector<double> sorted = values_;
    std::sort(sorted.begin(), sorted.end());
    const double rank = std::ceil(p / 100.0 * static_cast<double>(sorted.size()));
    const std::size_t index = static_cast<std::size_t>(std::clamp(rank, 1.0, double(sorted.size()))) - 1;
    return sorted[index];
}

}  // namespace vroc::hmd
