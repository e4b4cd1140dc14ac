// SPDX-License-Identifier: MIT
#include "pose_predictor.h"

#include "pose_math.h"

namespace vroc::plugins::predict {
using namespace plugin_sdk;

PosePredictor::PosePredictor(PredictMethod method, const KalmanTuning& t)
    : method_(method),
      position_filters_{AxisKalman(t.q_pos, t.r_pos, t.r_vel), AxisKalman(t.q_pos, t.r_pos, t.r_vel),
                        AxisKalman(t.q_pos, t.r_pos, t.r_vel)},
      rotation_filters_{AxisKalman(t.q_rot, t.r_rot, t.r_angvel), AxisKalman(t.q_rot, t.r_rot, t.r_angvel),
                        AxisKalman(t.q_rot, t.r_rot, t.r_angvel)} {}

void PosePredictor::add(const Measurement& m) {
    if (last_ && m.time_ns <= last_->time_ns) return;
    const bool has_v = m.linear_velocity.has_value(), has_w = m.angular_velocity.has_value();
    if (method_ == PredictMethod::Kalman) {
        const Eigen::Vector3d v = has_v ? *m.linear_velocity : Eigen::Vector3d::Zero();
        const Eigen::Vector3d w = has_w ? *m.angular_velocity : Eigen::Vector3d::Zero();
        if (!last_) {
            reference_ = m.orientation;
            for (int i = 0; i < 3; ++i) {
                position_filters_[i].reset(m.position[i], v[i], has_v);
                rotation_filters_[i].reset(0.0, w[i], has_w);
            }
        } else {
            const double dt = secondsOf(m.time_ns - last_->time_ns);
            // The measured orientation as an increment about the reference (small: the reference
            // follows the estimate after every update).
            const Eigen::Vector3d z = rotationVectorFromQuat(m.orientation * reference_.conjugate());
            for (int i = 0; i < 3; ++i) {
                position_filters_[i].predict(dt);
                position_filters_[i].update(m.position[i], v[i], has_v);
                rotation_filters_[i].predict(dt);
                rotation_filters_[i].update(z[i], w[i], has_w);
            }
            // Re-centre: fold the estimated increment into the reference.
            const Eigen::Vector3d increment(rotation_filters_[0].value(), rotation_filters_[1].value(),
                                            rotation_filters_[2].value());
            reference_ = (quatFromRotationVector(increment) * reference_).normalized();
            for (int i = 0; i < 3; ++i) rotation_filters_[i].shift(-increment[i]);
        }
    }
    previous_ = last_;
    last_ = m;
}

Prediction PosePredictor::predict(double ahead) const {
    switch (method_) {
        case PredictMethod::ConstantVelocity: return constantVelocity(ahead);
        case PredictMethod::Kalman: return kalman(ahead);
        case PredictMethod::None: break;
    }
    return {last_->position, last_->orientation, last_->linear_velocity.value_or(Eigen::Vector3d::Zero()),
            last_->angular_velocity.value_or(Eigen::Vector3d::Zero())};
}

Prediction PosePredictor::constantVelocity(double ahead) const {
    Eigen::Vector3d v = Eigen::Vector3d::Zero(), w = Eigen::Vector3d::Zero();
    const bool differences = previous_.has_value();
    const double dt = differences ? secondsOf(last_->time_ns - previous_->time_ns) : 0.0;
    if (last_->linear_velocity) v = *last_->linear_velocity;
    else if (differences) v = (last_->position - previous_->position) / dt;
    if (last_->angular_velocity) w = *last_->angular_velocity;
    else if (differences) w = rotationVectorFromQuat(last_->orientation * previous_->orientation.conjugate()) / dt;
    return {last_->position + v * ahead, (quatFromRotationVector(w * ahead) * last_->orientation).normalized(), v, w};
}

Prediction PosePredictor::kalman(double ahead) const {
    Prediction out;
    Eigen::Vector3d increment;
    for (int i = 0; i < 3; ++i) {
        const AxisKalman& p = position_filters_[i];
        const AxisKalman& r = rotation_filters_[i];
        out.position[i] = p.extrapolate(ahead);
        out.linear_velocity[i] = p.rate() + p.acceleration() * ahead;
        increment[i] = r.extrapolate(ahead);
        out.angular_velocity[i] = r.rate() + r.acceleration() * ahead;
    }
    out.orientation = (quatFromRotationVector(increment) * reference_).normalized();
    return out;
}

}  // namespace vroc::plugins::predict
