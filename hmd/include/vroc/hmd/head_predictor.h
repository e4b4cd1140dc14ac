// SPDX-License-Identifier: MIT
// Head-pose predictors: fed with tracker measurements in time order, they extrapolate the pose to
// a later time (the display time) to hide latency. Orientation is handled as an unwrapped
// world-frame rotation vector built from small increments between measurements.
#pragma once

#include <memory>

#include "vroc/core/math.h"
#include "vroc/hmd/hmd_settings.h"

namespace vroc::hmd {

class HeadPredictor {
public:
    virtual ~HeadPredictor() = default;
    /// A measurement of the head frame -> world pose taken at time t [s] (strictly increasing).
    virtual void addSample(double t, const Pose& pose) = 0;
    /// The predicted pose at time t [s] (>= the last sample's time). Identity before any sample.
    virtual Pose predict(double t) const = 0;
};

/// Tuning of the Kalman predictor (per axis, state: value, rate, acceleration).
struct KalmanTuning {
    double position_noise = 1e-4;      ///< [m] measurement standard deviation
    double angle_noise = 1e-3;         ///< [rad] measurement standard deviation
    double position_jerk = 50.0;       ///< [m/s^3] white-jerk process noise density (sqrt)
    double angle_jerk = 200.0;         ///< [rad/s^3] white-jerk process noise density (sqrt)
};

/// None: holds the newest measurement. ConstantVelocity: extrapolates the last two measurements.
/// Kalman: constant-acceleration Kalman filter per axis, after Azuma & Bishop 1994 (without
/// their inertial sensors).
std::unique_ptr<HeadPredictor> makePredictor(PredictorKind kind, const KalmanTuning& tuning = {});

}  // namespace vroc::hmd
