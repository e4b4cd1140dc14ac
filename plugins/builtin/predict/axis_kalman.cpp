// SPDX-License-Identifier: MIT
#include "axis_kalman.h"

#include <Eigen/Dense>

namespace vroc::plugin_sdk {

void AxisKalman::reset(double value, double rate, bool rate_measured) {
    x_ = Eigen::Vector3d(value, rate_measured ? rate : 0.0, 0.0);
    // Unknown rate and acceleration start with a wide prior (10 units/s, 100 units/s^2).
    p_ = Eigen::Vector3d(r_value_ * r_value_, rate_measured ? r_rate_ * r_rate_ : 100.0, 1e4).asDiagonal();
    initialised_ = true;
}

void AxisKalman::predict(double dt) {
    if (dt <= 0) return;
    Eigen::Matrix3d f;
    f << 1, dt, 0.5 * dt * dt, 0, 1, dt, 0, 0, 1;
    const double d2 = dt * dt, d3 = d2 * dt, d4 = d3 * dt, d5 = d4 * dt;
    Eigen::Matrix3d q;  // discretised white jerk
    q << d5 / 20, d4 / 8, d3 / 6, d4 / 8, d3 / 3, d2 / 2, d3 / 6, d2 / 2, dt;
    x_ = f * x_;
    p_ = f * p_ * f.transpose() + q_ * q;
}

void AxisKalman::update(double value, double rate, bool rate_measured) {
    if (rate_measured) {
        Eigen::Matrix<double, 2, 3> h;
        h << 1, 0, 0, 0, 1, 0;
        const Eigen::Vector2d z(value, rate);
        const Eigen::Matrix2d r = Eigen::Vector2d(r_value_ * r_value_, r_rate_ * r_rate_).asDiagonal();
        const Eigen::Matrix2d s = h * p_ * h.transpose() + r;
        const Eigen::Matrix<double, 3, 2> k = p_ * h.transpose() * s.inverse();
        x_ += k * (z - h * x_);
        p_ = (Eigen::Matrix3d::Identity() - k * h) * p_;
    } else {
        const Eigen::Vector3d k = p_.col(0) / (p_(0, 0) + r_value_ * r_value_);
        x_ += k * (value - x_[0]);
        p_ -= k * p_.row(0);
    }
    p_ = 0.5 * (p_ + p_.transpose());  // keep it symmetric against round-off
}

}  // namespace vroc::plugin_sdk
