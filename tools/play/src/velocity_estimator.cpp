// SPDX-License-Identifier: MIT
#include "vroc/play/velocity_estimator.h"

#include <algorithm>
#include <stdexcept>

#include <Eigen/Dense>

#include "vroc/core/rotation_vector.h"

namespace vroc::play {

VelocityEstimator::VelocityEstimator(int window, int degree) : window_(window), degree_(degree) {
    if (degree < 1 || degree > 2 || window < degree + 1)
        throw std::invalid_argument("VelocityEstimator: need degree 1 or 2 and window > degree");
}

void VelocityEstimator::add(double t, const Pose& pose) {
    if (!samples_.empty() && t <= samples_.back().t) return;   // keep times strictly increasing
    samples_.push_back({t, pose});
    while (static_cast<int>(samples_.size()) > window_) samples_.pop_front();
}

Vec3 VelocityEstimator::slope(const std::function<Vec3(const Sample&)>& value) const {
    if (!ready()) return Vec3::Zero();
    const int n = static_cast<int>(samples_.size());
    const double t0 = samples_.back().t;
    // Columns 1, (t - t0), (t - t0)^2: the coefficient of (t - t0) is the slope at t0.
    Eigen::MatrixXd a(n, degree_ + 1);
    Eigen::MatrixXd b(n, 3);
    for (int i = 0; i < n; ++i) {
        const double dt = samples_[i].t - t0;
        a(i, 0) = 1.0;
        a(i, 1) = dt;
        if (degree_ == 2) a(i, 2) = dt * dt;
        b.row(i) = value(samples_[i]).transpose();
    }
    const Eigen::MatrixXd coefficients = a.colPivHouseholderQr().solve(b);
    return coefficients.row(1).transpose();
}

Vec3 VelocityEstimator::linearVelocity() const {
    return slope([](const Sample& s) { return s.pose.position; });
}

Vec3 VelocityEstimator::angularVelocity() const {
    if (!ready()) return Vec3::Zero();
    const Quat newest = samples_.back().pose.orientation;
    // World-frame rotation from the newest orientation to each sample's; small within a window.
    return slope([&](const Sample& s) { return rotationVectorFromQuat(s.pose.orientation * newest.conjugate()); });
}

}  // namespace vroc::play
