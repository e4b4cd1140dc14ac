// SPDX-License-Identifier: MIT
// Time of contact by conservative advancement (CA) with a bisection fallback.
// The caller supplies the pair's signed distance as a function of time (it poses both bodies at t
// and asks the narrow phase); this file only schedules the queries. With tol = collision_distance:
//   - CA steps towards the target separation 0.75 tol, each step certified by the motion bounds
//     (the separation cannot fall below the target inside a step), so no contact is skipped;
//   - a hit is reported when the separation lies in the window [tol/2, tol];
//   - if a step lands below tol/2 anyway (the bounds were violated, e.g. an approximate distance),
//     the bracket is bisected until the separation lands in the window;
//   - a sample whose normal is not a unit vector is stepped with the direction-free bound.
// Box2D v3's b2TimeOfImpact uses the same window idea (target ± tolerance) and result states.
#pragma once

#include <cstdint>
#include <functional>

#include "scheduling/motion_bound.h"
#include "vroc/core/math.h"

namespace vroc::native {

/// One distance query at a time t. World frame.
struct DistanceSample {
    double distance = 0.0;        ///< [m] signed: > 0 separated, <= 0 penetrating
    Vec3 normal = Vec3::UnitX();  ///< unit, from A towards B (separating direction)
    Vec3 point_a = Vec3::Zero();  ///< [m] closest point on A
    Vec3 point_b = Vec3::Zero();  ///< [m] closest point on B
};

/// Distance of the pair with both bodies posed at time t [s] (absolute time, same clock as t0/t1).
using DistanceFunction = std::function<DistanceSample(double t)>;

struct ToiSettings {
    double collision_distance = 1e-3;   ///< [m] tol: contact when the separation is <= tol
    int max_iterations = 200;           ///< cap on distance queries after the first (CA + bisection)
};

enum class ToiState : std::uint8_t {
    /// Separation in [tol/2, tol] at `time`. If the motion bounds held (no bisection was needed),
    /// the separation stayed >= 0.75 tol on [t0, time]: `time` is no later than the first time
    /// the gap reaches 0.75 tol, so no earlier contact was skipped.
    Hit,
    /// The bounds prove separation >= 0.75 tol over the whole [t0, t1]. (A graze whose closest
    /// approach stays within (0.75 tol, tol] may be reported either way.)
    Separated,
    Overlapped,  ///< separation < tol/2 already at t0 (nothing to advance)
    Failed,      ///< iteration cap or no progress; `time` is the last certified (safe) time
};

const char* toString(ToiState state);

struct ToiResult {
    ToiState state = ToiState::Failed;
    double time = 0.0;          ///< [s] Hit: the TOI; Separated: t1; Overlapped: t0; Failed: safe time
    DistanceSample sample;      ///< the last distance query (at `sample_time`)
    double sample_time = 0.0;   ///< [s]
    int iterations = 0;         ///< distance queries after the first (= advancement + bisection)
    int advancement_steps = 0;  ///< CA steps taken
    int bisection_steps = 0;    ///< bisection halvings taken
};

/// Time of contact of A and B in [t0, t1]. `a` and `b` bound each body's motion from t0 on
/// (their velocities are those at t0). Needs collision_distance > 0 and t1 >= t0.
ToiResult conservativeAdvancement(const DistanceFunction& distance, const MotionBound& a,
                                  const MotionBound& b, double t0, double t1,
                                  const ToiSettings& settings);

/// The bisection fallback on its own: a bracket with separation > tol at t_a and < tol/2 at t_b
/// (samples given), halved until a midpoint's separation lies in [tol/2, tol]. The result is Hit,
/// or Failed after `max_iterations` halvings. If the separation changes at most v |Δt| over the
/// bracket, the halvings needed are at most ⌈log₂(v (t_b − t_a) / tol)⌉ + 1.
ToiResult bisectContact(const DistanceFunction& distance, double t_a, const DistanceSample& at_a,
                        double t_b, const DistanceSample& at_b, const ToiSettings& settings);

}  // namespace vroc::native
