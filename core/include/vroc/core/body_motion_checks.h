// SPDX-License-Identifier: MIT
// Checks a backend makes on a scene body before it builds its own copy. One home, so that every
// backend refuses the same bodies for the same reason.
#pragma once

#include "vroc/core/scene.h"

namespace vroc {

/// True when a tracked body's prescribed motion can be followed: finite position, a finite,
/// non-zero quaternion (normalised by the backend) and finite linear [m/s] and angular [rad/s]
/// velocities. The loader already refuses such files; this guards scenes built in code.
inline bool hasFiniteMotion(const Body& body) {
    return body.pose.position.allFinite() && body.pose.orientation.coeffs().allFinite() &&
           body.pose.orientation.norm() > 0.0 && body.linear_velocity.allFinite() &&
           body.angular_velocity.allFinite();
}

}  // namespace vroc
