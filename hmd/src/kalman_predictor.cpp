// SPDX-License-Identifier: MIT
#include "kalman_predictor.h"

#include "vroc/core/rotation_vector.h"

namespace vroc::hmd {

void KalmanPredictor::Axis::initialise(double value, double measurement_sigma) {
    x = Eigen::Vector3d(value, 0.0, 0.0);
    p = Eigen::Vector3d(measurement_sigma * measurement_sigma, 1e4, 1e6).asDiagonal();
}

void KalmanPredictor::Axis::step(double dt, double jerk_density, double sigma, double z) {
    Eigen::Matrix3d f;
    f << 1, dt, 0.5 * dt * dt, 0, 1, dt, 0, 0, 1;
    // Discrete white-jerk process noise (Bar-Shalom), scaled by the jerk density squared.
    const double q = jerk_density * jerk_density;
    const double d2 = dt * dt, d3 = d2 * dt, d4 = d3 * dt, d5 = d4 * dt;
    Eigen::Matrix3d qm;
    qm << d5 / 20, d4 / 8, d3 / 6, d4 / 8, d3 / 3, d2 / 2, d3 / 6, d2 / 2, dt;
    x = f * x;
    p = f * p * f.transpose() + q * qm;
    // Measurement of the value only: H = [1 0 0].
    const double s = p(0, 0) + sigma * sigma;
    const Eigen::Vector3d k = p.col(0) / s;
    x += k * (z - x(0));
    p -= k * p.row(0);
    p = 0.5 * (p + p.transpose());   // keep it symmetric against rounding
}

void KalmanPredictor::addSample(double t, const Pose& pose) {
    if (count_ == 0) {
        unwrapped_ = rotationVectorFromQuat(pose.orientation);
        for (int i = 0; i < 3; ++i) axes_[i].initialise(pose.position[i], tuning_.position_noise);
        for (int i = 0; i < 3; ++i) axes_[3 + i].initialise(unwrapped_[i], tuning_.angle_noise);
    } else if (t > time_) {
        const double dt = t - time_;
        // World-frame increment since the previous sample: small, so summing them unwraps.
        unwrapped_ += rotationVectorFromQuat(pose.orientation * last_.orientation.conjugate());
        for (int i = 0; i < 3; ++i) axes_[i].step(dt, tuning_.position_jerk, tuning_.position_noise, pose.position[i]);
        for (int i = 0; i < 3; ++i) axes_[3 + i].step(dt, tuning_.angle_jerk, tuning_.angle_noise, unwrapped_[i]);
    }
    last_ = pose;
    time_ = t;
    ++count_;
}

Pose KalmanPredictor::predict(double t) const {
    if (count_ == 0) return last_;
    const double h = t - time_;
    Vec3 position, angle;
    for (int i = 0; i < 3; ++i) {
        const auto& a = axes_[i].x;
        position[i] = a(0) + a(1) * h + 0.5 * a(2) * h * h;
        const auto& b = axes_[3 + i].x;
        angle[i] = b(0) + b(1) * h + 0.5 * b(2) * h * h;
    }
    // Anchor the rotation on the newest measurement: apply the predicted change since it.
    const Quat change = quatFromRotationVector(angle - unwrapped_);
    return {position, (change * last_.orientation).normalized()};
}

}  // namespace vroc::hmd
