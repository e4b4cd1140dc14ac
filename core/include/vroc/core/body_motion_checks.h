// SPDX-License-Identifier: MIT
// Checks a backend makes on a scene body before it builds its own copy. One home, so that every
// backend refuses the same bodies for the same reason.
#pragma once

#include <functional>
#include <string>

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

/// The checks a backend that builds its own copy of the scene makes on every body before it creates
/// anything, so that a refused scene leaves nothing behind: a material index in range, a shape the
/// engine supports (`unsupported` gives the reason, empty if supported), a finite pose with a
/// non-zero quaternion, finite initial velocities for a body that moves, and a virtual body's
/// positive finite mass and positive definite inertia. Throws InputError
/// "<engine>: scene '<scene>': body '<body>': <what was expected>".
void checkBodiesForEngine(const Scene& scene, const std::string& engine,
                          const std::function<std::string(const Shape&)>& unsupported);

}  // namespace vroc
