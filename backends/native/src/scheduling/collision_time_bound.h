// SPDX-License-Identifier: MIT
// earliestCollisionTime: a lower bound on when two bodies could first touch, from their current
// gap and their motion bounds (the key of the collision queue, and the step of conservative
// advancement). Conservative: never later than the true time, provided the motion bounds hold.
#pragma once

#include <limits>

#include "scheduling/motion_bound.h"
#include "vroc/core/math.h"

namespace vroc::native {

inline constexpr double kNever = std::numeric_limits<double>::infinity();

/// Earliest t in [0, horizon] at which the gap [m] (distance minus the collision distance) could
/// close, given a separating direction `normal_ab` (unit, from A towards B; A's support plane
/// along +n and B's along −n approach each other). Bodies' bounds are given at t = 0.
/// Returns 0 if gap <= 0, kNever if the gap cannot close within `horizon` [s].
/// The approach is n·(v_A − v_B) t + ½ n·(a_A − a_B) t² + rot_A(t) + rot_B(t), with
/// rot(t) = min(|ω| R t, R − r) (or the single term chosen by rotation_term); it is solved
/// piecewise exactly (each piece is a quadratic).
double earliestCollisionTime(double gap, const Vec3& normal_ab, const MotionBound& a,
                             const MotionBound& b, double horizon);

/// Direction-free variant (no normal known, e.g. from a bounding-sphere gap): the COM terms become
/// |v_A − v_B| t + ½ |a_A − a_B| t².
double earliestCollisionTime(double gap, const MotionBound& a, const MotionBound& b,
                             double horizon);

}  // namespace vroc::native
