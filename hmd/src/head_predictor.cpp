// SPDX-License-Identifier: MIT
// makePredictor and the two simple predictors: hold the newest measurement, or extrapolate its
// velocity (the Kalman predictor is kalman_predictor.cpp).
#include "vroc/hmd/head_predictor.h"
#include "vroc/core/rotation_vector.h"
#include "kalman_predictor.h"

namespace vroc::hmd {
namespace {

class HoldPredictor final : public HeadPredictor {
public:
    void addSample(double, const Pose& pose) override { last_ = pose; }
    Pose predict(double) const override { return last_; }

private:
    Pose last_;
};

/// Velocity from the last two samples (world-frame angular velocity), extrapolated linearly.
class ConstantVelocityPredictor final : public HeadPredictor {
public:
    void addSample(double t, const Pose& pose) override {
        if (count_ > 0 && t > time_) {
            const double dt = t - time_;
            linear_ = (pose.position - last_.position) / dt;
            angular_ = rotationVectorFromQuat(pose.orientation * last_.orientation.conjugate()) / dt;
        }
        last_ = pose;
        time_ = t;
        ++count_;
    }
    Pose predict(double t) const override {
        const double h = t - time_;
        return {last_.position + linear_ * h, (quatFromRotationVector(angular_ * h) * last_.orientation).normalized()};
    }

private:
    Pose last_;
    double time_ = 0.0;
    int count_ = 0;
    Vec3 linear_ = Vec3::Zero();    // [m/s]
    Vec3 angular_ = Vec3::Zero();   // [rad/s] world frame
};

}  // namespace

std::unique_ptr<HeadPredictor> makePredictor(PredictorKind kind, const KalmanTuning& tuning) {
    switch (kind) {
        case PredictorKind::ConstantVelocity: return std::make_unique<ConstantVelocityPredictor>();
        case PredictorKind::Kalman: return std::make_unique<KalmanPredictor>(tuning);
        default: return std::make_unique<HoldPredictor>();
    }
}

}  // namespace vroc::hmd
