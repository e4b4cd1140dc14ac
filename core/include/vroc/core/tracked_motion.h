// SPDX-License-Identifier: MIT
// A tracked body's motion between tracker samples (scene.h: BodyRole::Tracked). From the sample
// taken at t0 the body frame moves at the constant linear velocity v of its origin and the constant
// angular velocity w (both world frame), so at time t
//     position = p0 + v (t - t0),   orientation = exp(w (t - t0)) q0   (a turn by |w| (t - t0) about w).
// The pose is computed from the sample each time, never integrated, so it does not drift.
#pragma once

#include "vroc/core/backend.h"

namespace vroc {

struct TrackedMotion {
    double t0 = 0.0;     ///< [s] simulation time of the sample
    BodyState sample;    ///< pose at t0 (unit quaternion); origin's linear velocity [m/s], angular [rad/s], world

    /// Body frame -> world at time `t` [s].
    Pose poseAt(double t) const;
};

}  // namespace vroc
