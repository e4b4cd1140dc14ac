// SPDX-License-Identifier: MIT
// Constant-acceleration Kalman predictor (after Azuma & Bishop 1994, position-only measurements):
// six independent axes (position x, y, z and the unwrapped world rotation vector), each with
// state [value, rate, acceleration] driven by white jerk.
#pragma once

#include <array>

#include <Eigen/Core>

#include "vroc/hmd/head_predictor.h"

namespace vroc::hmd {

class KalmanPredictor final : public HeadPredictor {
public:
    explicit KalmanPredictor(const KalmanTuning& tuning) : tuning_(tuning) {}
    void addSample(double t, const Pose& pose) override;
    Pose predict(double t) const override;

private:
    struct Axis {
        Eigen::Vector3d x = Eigen::Vector3d::Zero();        // value, rate, acceleration
        Eigen::Matrix3d p = Eigen::Matrix3d::Identity() * 1e6;
        void initialise(double value, double measurement_sigma);
        void step(double dt, double jerk_density, double measurement_sigma, double z);
    };
    KalmanTuning tuning_;
    std::array<Axis, 6> axes_;
    Pose last_;                            // newest measurement
    Vec3 unwrapped_ = Vec3::Zero();        // [rad] accumulated rotation vector of the newest sample
    double time_ = 0.0;
    int count_ = 0;
};

}  // namespace vroc::hmd
