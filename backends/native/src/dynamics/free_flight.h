// SPDX-License-Identifier: MIT
// Flight between collisions: gravity in closed form, torque-free rotation with the world angular
// momentum held fixed (so it is conserved exactly) and the rotational energy kept on its level set.
#pragma once

#include "dynamics/rigid_body.h"

namespace vroc::native {

/// Largest rotation angle [rad] per internal RK4 sub-step of the orientation.
inline constexpr double kMaxSubstepAngle = 0.01;

/// [rad/s] The largest |ω| a body reaches in torque-free flight, from its two invariants: the
/// squared angular momentum |L|² and twice its rotational energy, 2E = L·ω. In principal axes, with
/// x_i = ω_i² ≥ 0, Σ I_i x_i = 2E and Σ I_i² x_i = |L|²: |ω|² = Σ x_i is largest at an end of that
/// segment, where one x_i is zero (the polhode passes through both ends, so the bound is met).
/// `moments` are the principal moments, ascending. Never more than |L| / I_min; a body spinning
/// about its major axis gets its own |ω| (a thin rod at 50 rad/s: 50, where |L| / I_min gives 1,250
/// times that). Negative if no end is found (the caller keeps |L| / I_min).
double torqueFreeSpeedBound(const Vec3& moments, double l_squared, double twice_energy);

/// Ballistic translation: com += v h + g h^2/2, v += g h. Exact in floating point terms.
/// Kinematic (tracked) bodies: com += v h.
void advanceBallistic(RigidBody& body, double h, const Vec3& gravity);

/// Torque-free rotation over `h` [s]: L (world) unchanged. Isotropic bodies (ω constant) rotate in
/// closed form, q <- exp(ω h / 2) q (returns 1). Others: orientation by RK4 sub-steps of at most
/// kMaxSubstepAngle, then projected back onto the energy level set (|R^T L| is kept by R itself).
/// Returns the number of sub-steps taken.
int advanceTorqueFree(RigidBody& body, double h);

}  // namespace vroc::native
