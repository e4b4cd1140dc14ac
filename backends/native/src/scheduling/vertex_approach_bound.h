// SPDX-License-Identifier: MIT
// vertexApproachTime: when two convex parts could first close below a floor, judged support point
// by support point along a fixed direction n.
//
// The pair bound of collision_time_bound.h moves every surface point as if it were the closest one
// at the fastest speed (|ω| R on the smallest gap): a box tipping over an edge in a pile gets its
// island re-solved every millisecond. Here each support point (a polytope's vertex, a sphere's
// centre) keeps its own height along n and its own first-order speed (v + ω × ρ)·n; only the change
// of that speed is bounded, by (|ω̇| + |ω|²)|ρ|. The contact points, held by the solver, approach at
// their solved speed, and the vertices that rotation brings down start from their own, larger gaps.
//
// Why it is safe: for any unit n, dist(A, B) ≥ σ = min_{y∈B} n·y − max_{x∈A} n·x, and over a
// polytope both extremes lie at vertices (a sphere: its centre ± radius). A point at offset ρ from
// the COM obeys  n·x(t) ≤ n·x₀ + t n·(v + ω₀ × ρ) + ½ t² (n·a + K |ρ|)  while K bounds |ω̇| + |ω|²
// over [0, t] (K = rotationCurvatureBound). So σ(t) ≥ min over point pairs of a quadratic in t, and
// the first time any of those quadratics reaches the floor is a lower bound on when the parts can.
// World frame, SI units; plain functions, nothing kept.
#pragma once

#include <vector>

#include "vroc/core/math.h"

namespace vroc::native {

/// How a body moves from t = 0 on, as the per-point bound needs it (all world frame).
struct RigidMotion {
    Vec3 com = Vec3::Zero();                ///< [m] COM at t = 0
    Vec3 velocity = Vec3::Zero();           ///< [m/s] COM velocity at t = 0
    Vec3 acceleration = Vec3::Zero();       ///< [m/s^2] constant COM acceleration
    Vec3 angular_velocity = Vec3::Zero();   ///< [rad/s] ω at t = 0
    /// [1/s^2] K ≥ |ω̇| + |ω|² over the interval: |d²/dt² (R(t) ρ)| ≤ K |ρ|.
    double curvature = 0.0;

    /// A body that does not move (static, asleep).
    static RigidMotion stationary(const Vec3& com) {
        RigidMotion m;
        m.com = com;
        return m;
    }
};

/// [s] The first t >= 0 with speed t + ½ accel t² >= slack (slack > 0), or kNever: the smaller
/// positive root, in the stable form (a height rising towards a level; the per-point bound here, and
/// the fixed ticks' looks at a predicted closing).
double firstReach(double slack, double speed, double accel);

/// [1/s^2] K for a body with world angular momentum |L| [kg m^2/s], constant world torque |τ| [N m]
/// and smallest principal moment I_min [kg m^2], over an interval of `duration` [s]:
/// |L| ≤ L_max = |L| + |τ| T, |ω| ≤ Ω = L_max / I_min, and Euler's equation in world axes,
/// ω̇ = I⁻¹ (τ − ω × L), gives |ω̇| ≤ (|τ| + Ω L_max) / I_min; for an isotropic body ω × L = 0, so
/// |ω̇| ≤ |τ| / I. Returns +inf if I_min ≤ 0 while the body spins or is torqued.
double rotationCurvatureBound(double angular_momentum, double torque, double smallest_moment, double duration,
                              bool isotropic);

/// One part's support points: world positions [m] and a pad [m] added outward along ±n (a sphere's
/// radius; 0 for polytope vertices).
struct SupportPoints {
    std::vector<Vec3> points;
    double pad = 0.0;
};

/// Earliest t in [0, horizon] [s] at which σ(t) (the separation of A and B projected on the unit
/// direction `normal_ab`, from A towards B) could fall below `floor` [m]; kNever if it cannot within
/// the horizon, 0 if it already is below. Conservative provided the motions hold over the horizon.
double vertexApproachTime(const SupportPoints& a, const RigidMotion& ma, const SupportPoints& b,
                          const RigidMotion& mb, const Vec3& normal_ab, double floor, double horizon);

}  // namespace vroc::native
