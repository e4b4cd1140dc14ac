// SPDX-License-Identifier: MIT
// A one-axis Kalman filter with a constant-acceleration model (state: value, rate, acceleration;
// white jerk as process noise), measuring the value and optionally the rate. Six of them predict a
// pose ahead of its latest measurement (three for position, three for orientation as a rotation
// vector): the HMD model's head predictor (hmd) and the `predict` device plugin. After Azuma &
// Bishop 1994, who predicted head motion with such filters to hide latency.
// Header-only on purpose: the built-in device plugins link nothing of core.
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>

namespace vroc {

/// Variances of what an AxisKalman's first measurement leaves unknown.
struct AxisKalmanPrior {
    double rate_variance = 100.0;           ///< [unit^2/s^2] unless the rate is measured
    double acceleration_variance = 1e4;     ///< [unit^2/s^4]
};

class AxisKalman {
public:
    using Prior = AxisKalmanPrior;

    /// q: jerk spectral density [unit^2/s^5]; r_value, r_rate: measurement standard deviations
    /// [unit], [unit/s] (r_rate only matters when rates are measured).
    AxisKalman(double q, double r_value, double r_rate = 0.0) : q_(q), r_value_(r_value), r_rate_(r_rate) {}

    bool initialised() const { return initialised_; }
    /// Starts from a first measurement of the value (and of the rate when rate_measured).
    void reset(double value, double rate, bool rate_measured, const Prior& prior = {}) {
        x_ = Eigen::Vector3d(value, rate_measured ? rate : 0.0, 0.0);
        p_ = Eigen::Vector3d(r_value_ * r_value_, rate_measured ? r_rate_ * r_rate_ : prior.rate_variance,
                             prior.acceleration_variance)
                 .asDiagonal();
        initialised_ = true;
    }

    /// Advances the state by dt [s]; nothing for dt <= 0.
    void predict(double dt) {
        if (dt <= 0) return;
        Eigen::Matrix3d f;
        f << 1, dt, 0.5 * dt * dt, 0, 1, dt, 0, 0, 1;
        // Discretised white jerk (Bar-Shalom), scaled by the spectral density.
        const double d2 = dt * dt, d3 = d2 * dt, d4 = d3 * dt, d5 = d4 * dt;
        Eigen::Matrix3d q;
        q << d5 / 20, d4 / 8, d3 / 6, d4 / 8, d3 / 3, d2 / 2, d3 / 6, d2 / 2, dt;
        x_ = f * x_;
        p_ = f * p_ * f.transpose() + q_ * q;
    }

    /// Measurement of the value (and of the rate when rate_measured).
    void update(double value, double rate, bool rate_measured) {
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
            // H = [1 0 0]: the gain is P's first column over the innovation variance.
            const Eigen::Vector3d k = p_.col(0) / (p_(0, 0) + r_value_ * r_value_);
            x_ += k * (value - x_[0]);
            p_ -= k * p_.row(0);
        }
        p_ = 0.5 * (p_ + p_.transpose());   // keep it symmetric against round-off
    }

    /// Shifts the value (used to re-centre orientation increments on a moving reference).
    void shift(double delta) { x_[0] += delta; }

    double value() const { return x_[0]; }
    double rate() const { return x_[1]; }
    double acceleration() const { return x_[2]; }
    /// value + rate t + acceleration t^2 / 2: the constant-acceleration extrapolation t [s] ahead.
    double extrapolate(double t) const { return x_[0] + x_[1] * t + 0.5 * x_[2] * t * t; }

private:
    double q_, r_value_, r_rate_;
    bool initialised_ = false;
    Eigen::Vector3d x_ = Eigen::Vector3d::Zero();
    Eigen::Matrix3d p_ = Eigen::Matrix3d::Identity();
};

}  // namespace vroc
