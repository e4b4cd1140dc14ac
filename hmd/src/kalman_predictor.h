// SPDX-License-Identifier: MIT
// Constant-acceleration Kalman predictor (after Azuma & Bishop 1994, position-only measurements):
// six independent axes (vroc/core/axis_kalman.h: position x, y, z and the unwrapped world rotation
// vector), each with state [value, rate, acceleration] driven by white jerk.
#pragma once

#include <array>

#include "vroc/core/axis_kalman.h"
#include "vroc/hmd/head_predictor.h"

namespace vroc::hmd {

class KalmanPredictor final : public HeadPredictor {
public:
    explicit KalmanPredictor(const KalmanTuning& tuning);
    void addSample(double t, const Pose& pose) override;
    Pose predict(double t) const override;

private:
    std::array<AxisKalman, 6> axes_;       // position x, y, z; rotation vector x, y, z
    Pose last_;                            // newest measurement
    Vec3 unwrapped_ = Vec3::Zero();        // [rad] accumulated rotation vector of the newest sample
    double time_ = 0.0;
    int count_ = 0;
};

}  // namespace vroc::hmd
