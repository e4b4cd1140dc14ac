// SPDX-License-Identifier: MIT
// Flight between collisions: gravity in closed form, torque-free rotation with the world angular
// momentum held fixed (so it is conserved exactly) and the rotational energy kept on its level set.
#pragma once

#include "dynamics/rigid_body.h"

namespace vroc::native {

/// Largest rotation angle [rad] per internal RK4 sub-step of the orientation.
inline constexpr double kMaxSubstepAngle = 0.01;

/// Ballistic translation: com += v h + g h^2/2, v += g h. Exact in floating point terms.
/// Kinematic (tracked) bodies: com += v h.
void advanceBallistic(RigidBody& body, double h, const Vec3& gravity);

/// Torque-free rotation over `h` [s]: L (world) unchanged. Isotropic bodies (ω constant) rotate in
/// closed form, q <- exp(ω h / 2) q (returns 1). Others: orientation by RK4 sub-steps of at most
/// kMaxSubstepAngle, then projected back onto the energy level set (|R^T L| is kept by R itself).
/// Returns the number of sub-steps taken.
int advanceTorqueFree(RigidBody& body, double h);

}  // namespace vroc::native
