// SPDX-License-Identifier: MIT
#include "kalman_predictor.h"

#include "vroc/core/rotation_vector.h"

namespace vroc::hmd {
namespace {

// The first sample leaves rate and acceleration wide open.
constexpr AxisKalman::Prior kPrior{1e4, 1e6};

AxisKalman positionAxis(const KalmanTuning& t) { return {t.position_jerk * t.position_jerk, t.position_noise}; }
AxisKalman angleAxis(const KalmanTuning& t) { return {t.angle_jerk * t.angle_jerk, t.angle_noise}; }

}  // namespace

KalmanPredictor::KalmanPredictor(const KalmanTuning& tuning)
    : axes_{positionAxis(tuning), positionAxis(tuning), positionAxis(tuning),
            angleAxis(tuning),    angleAxis(tuning),    angleAxis(tuning)} {}

void KalmanPredictor::addSample(double t, const Pose& pose) {
    if (count_ == 0) {
        unwrapped_ = rotationVectorFromQuat(pose.orientation);
        for (int i = 0; i < 3; ++i) axes_[i].reset(pose.position[i], 0.0, false, kPrior);
        for (int i = 0; i < 3; ++i) axes_[3 + i].reset(unwrapped_[i], 0.0, false, kPrior);
    } else if (t > time_) {
        const double dt = t - time_;
        // World-frame increment since the previous sample: small, so summing them unwraps.
        unwrapped_ += rotationVectorFromQuat(pose.orientation * last_.orientation.conjugate());
        for (int i = 0; i < 6; ++i) {
            axes_[i].predict(dt);
            axes_[i].update(i < 3 ? pose.position[i] : unwrapped_[i - 3], 0.0, false);
        }
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
        position[i] = axes_[i].extrapolate(h);
        angle[i] = axes_[3 + i].extrapolate(h);
    }
    // Anchor the rotation on the newest measurement: apply the predicted change since it.
    const Quat change = quatFromRotationVector(angle - unwrapped_);
    return {position, (change * last_.orientation).normalized()};
}

}  // namespace vroc::hmd
