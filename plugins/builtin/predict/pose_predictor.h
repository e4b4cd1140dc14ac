// SPDX-License-Identifier: MIT
// Predicts a sensor's pose ahead of its newest measurement. Methods:
//  - None: the measurement as is (what a system without prediction draws);
//  - ConstantVelocity: p + v dt, q <- exp(w dt) q, with the device's velocities when it reports
//    them and finite differences of the last two measurements otherwise;
//  - Kalman: constant-acceleration Kalman filters on position and on orientation (as rotation-
//    vector increments about a reference that follows the estimate), extrapolated.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "vroc/core/axis_kalman.h"

namespace vroc::plugins::predict {

enum class PredictMethod { None, ConstantVelocity, Kalman };

struct KalmanTuning {
    double q_pos = 50.0;       ///< jerk spectral density, position [m^2/s^5]
    double r_pos = 1e-3;       ///< position measurement sd [m]
    double r_vel = 0.05;       ///< linear velocity measurement sd [m/s]
    double q_rot = 500.0;      ///< jerk spectral density, orientation [rad^2/s^5]
    double r_rot = 2e-3;       ///< orientation measurement sd [rad]
    double r_angvel = 0.05;    ///< angular velocity measurement sd [rad/s]
};

struct Measurement {
    int64_t time_ns;
    Eigen::Vector3d position;
    Eigen::Quaterniond orientation;
    std::optional<Eigen::Vector3d> linear_velocity;   ///< base frame
    std::optional<Eigen::Vector3d> angular_velocity;  ///< base frame
};

struct Prediction {
    Eigen::Vector3d position;
    Eigen::Quaterniond orientation;
    Eigen::Vector3d linear_velocity;
    Eigen::Vector3d angular_velocity;
};

class PosePredictor {
public:
    PosePredictor(PredictMethod method, const KalmanTuning& tuning);
    /// Feeds a measurement newer than the last one (older or equal times are ignored).
    void add(const Measurement& m);
    bool empty() const { return !last_.has_value(); }
    int64_t lastTime() const { return last_->time_ns; }
    /// The pose `ahead` seconds after the newest measurement.
    Prediction predict(double ahead) const;

private:
    Prediction constantVelocity(double ahead) const;
    Prediction kalman(double ahead) const;

    PredictMethod method_;
    std::optional<Measurement> last_, previous_;
    std::array<AxisKalman, 3> position_filters_, rotation_filters_;
    Eigen::Quaterniond reference_ = Eigen::Quaterniond::Identity();  // orientation = exp(increment) * reference
};

}  // namespace vroc::plugins::predict
