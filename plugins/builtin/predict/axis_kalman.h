// SPDX-License-Identifier: MIT
// A one-axis Kalman filter with a constant-acceleration model (state: value, rate, acceleration;
// white jerk as process noise), measuring the value and optionally the rate. Three of them track
// a position; three more track an orientation as rotation-vector increments (PosePredictor).
// After Azuma & Bishop 1994, who predicted head motion with such filters to hide latency.
#pragma once

#include <Eigen/Core>

namespace vroc::plugin_sdk {

class AxisKalman {
public:
    /// q: jerk spectral density [unit^2/s^5]; r_value, r_rate: measurement standard deviations.
    AxisKalman(double q, double r_value, double r_rate) : q_(q), r_value_(r_value), r_rate_(r_rate) {}

    bool initialised() const { return initialised_; }
    void reset(double value, double rate, bool rate_measured);
    /// Advances the state by dt [s] (dt >= 0).
    void predict(double dt);
    /// Measurement of the value (and of the rate when rate_measured).
    void update(double value, double rate, bool rate_measured);
    /// Shifts the value (used to re-centre the orientation increments).
    void shift(double delta) { x_[0] += delta; }

    double value() const { return x_[0]; }
    double rate() const { return x_[1]; }
    double acceleration() const { return x_[2]; }
    /// value + rate t + acceleration t^2 / 2: the constant-acceleration extrapolation.
    double extrapolate(double t) const { return x_[0] + x_[1] * t + 0.5 * x_[2] * t * t; }

private:
    double q_, r_value_, r_rate_;
    bool initialised_ = false;
    Eigen::Vector3d x_ = Eigen::Vector3d::Zero();
    Eigen::Matrix3d p_ = Eigen::Matrix3d::Identity();
};

}  // namespace vroc::plugin_sdk
