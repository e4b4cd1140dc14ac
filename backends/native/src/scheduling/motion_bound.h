// SPDX-License-Identifier: MIT
// MotionBound: how far a rigid body's surface can move over [0, t] when its centre of mass (COM)
// flies a parabola (velocity v, constant acceleration a) and it spins no faster than |ω|.
// Two questions are answered, and they differ:
//   - maxDisplacement(t): how far any single surface point can travel (swept boxes);
//   - approachBound(n, t): how far the body's support plane along a unit direction n can advance,
//     i.e. the growth of the support function h(n) = max_x n·x. This is what closes a gap
//     between convex bodies whose separating plane has normal n (docs/native-scheduling.md).
// Rotation enters through two safe bounds, the tighter of which is used:
//   - the paper's rate-independent margin R − r (any orientation keeps h(n) in [r, R] about the COM);
//   - the rate-based chord 2R sin(min(|ω|t, π)/2) ≤ min(|ω| R t, 2R).
// All vectors world frame, SI units. Plain data: the caller owns it and copies it freely.
#pragma once

#include "scheduling/aabb.h"
#include "vroc/core/math.h"

namespace vroc::native {

/// Which rotation term the bounds use. `Tightest` (the default) is the safe minimum of both;
/// the other two exist to compare against the paper and against rate-only schemes.
enum class RotationTerm { Tightest, PaperMargin, RateOnly };

struct MotionBound {
    Vec3 velocity = Vec3::Zero();       ///< [m/s] COM velocity at the interval start (t = 0), world
    Vec3 acceleration = Vec3::Zero();   ///< [m/s^2] constant COM acceleration (gravity), world
    /// [rad/s] upper bound on |ω(t)| over the whole interval. Torque-free asymmetric bodies do not
    /// keep |ω| constant: |L| / I_min is a safe bound (|L| = |Iω| ≥ I_min |ω|).
    double angular_speed = 0.0;
    double outer_radius = 0.0;   ///< [m] R: largest distance from the COM to a point of the shape
    /// [m] r: radius of the largest COM-centred ball inside the shape (0 when unknown or when the
    /// COM lies outside the shape). Clamped to [0, R] by the bounds.
    double inner_radius = 0.0;
    RotationTerm rotation_term = RotationTerm::Tightest;

    /// A body that does not move (real / static objects): every bound is 0.
    static MotionBound stationary() { return {}; }

    /// The same body seen from time `dt` on: velocity v + a·dt, everything else unchanged.
    MotionBound advanced(double dt) const;

    /// True when every field is finite (R may be +inf only if angular_speed is 0) and non-negative
    /// where it must be.
    bool valid() const;

    /// [m] R − r, the paper's rotation margin (rate-independent, any rotation angle).
    double rotationMargin() const;
    /// [m] largest displacement of any point by rotation alone: 2R sin(min(|ω|t, π)/2).
    double chordBound(double t) const;
    /// [m] growth of the support function along any direction caused by rotation alone over [0, t]:
    /// the selected rotation term (Tightest: min(chord, R − r)).
    double rotationApproach(double t) const;
    /// [m] n·(v t + ½ a t²): COM advance along the unit direction n at time t (may be negative).
    double translationAlong(const Vec3& n, double t) const;
    /// [m] upper bound on the advance of the support plane along unit n at time t:
    /// n·(v t + ½ a t²) + rotationApproach(t).
    double approachBound(const Vec3& n, double t) const;
    /// [m] max over s in [0, t] of |v s + ½ a s²|, bounded by |v| t + ½ |a| t².
    double maxTranslation(double t) const;
    /// [m] upper bound on how far any surface point can move over [0, t] (any direction).
    double maxDisplacement(double t) const;
    /// The box `at_start` (the body's AABB at t = 0) grown to contain the body over [0, h]:
    /// per axis the COM parabola's range plus the rotation term (support-function argument).
    Aabb sweptAabb(const Aabb& at_start, double h) const;
};

}  // namespace vroc::native
