// SPDX-License-Identifier: MIT
#include "vroc/core/tracked_motion.h"

namespace vroc {

Pose TrackedMotion::poseAt(double t) const {
    const double tau = t - t0;
    Pose p;
    p.position = sample.pose.position + sample.linear_velocity * tau;
    const double rate = sample.angular_velocity.norm();
    const Quat turn =
        rate > 0.0 ? Quat(Eigen::AngleAxisd(rate * tau, sample.angular_velocity / rate)) : Quat::Identity();
    p.orientation = (turn * sample.pose.orientation).normalized();
    return p;
}

}  // namespace vroc
