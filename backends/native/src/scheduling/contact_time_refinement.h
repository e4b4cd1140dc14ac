// SPDX-License-Identifier: MIT
// Contact time refinement: a pair met inside the collision window (gap in (0, collision_distance])
// and still approaching is not resolved there. Its bodies fly exactly (ballistic COM, torque-free
// rotation), so the pair's gap can be evaluated at any later time; conservative advancement on
// the motion bounds, aimed at half of a tiny gap, finds the first time the gap is in
// [0, gap_max] (gap_max ~ 1e-9 of the bodies' size) and the impact is resolved there: bounce
// heights then follow e^(2n) h from the surface, not from the window (issue 4, ball drop).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "backend/body_shape.h"
#include "dynamics/rigid_body.h"
#include "narrowphase/proximity.h"
#include "scheduling/motion_bound.h"
#include "scheduling/time_of_contact.h"

namespace vroc::native {

/// Every part pair's gap of one body pair with both bodies posed at absolute time t [s]; world.
using PartGapsFunction = std::function<std::vector<DistanceSample>(double t)>;

enum class RefineState : std::uint8_t {
    Touching,   ///< smallest gap in [0, gap_max] at `time`
    Clear,      ///< the bounds prove the smallest gap stays >= gap_max / 2 over [t0, t1]; time = t1
    Advanced,   ///< query cap hit: `time` > t0 is the last certified time (gap > gap_max there)
    Failed,     ///< no progress (time = t0)
};

struct RefineResult {
    RefineState state = RefineState::Failed;
    double time = 0.0;   ///< [s] absolute
    double gap = 0.0;    ///< [m] smallest part gap at `time`
    int queries = 0;     ///< gap evaluations after the one at t0
};

/// Refines the contact time of a pair whose smallest gap at t0 (`at_t0`, > gap_max) lies inside the
/// collision window. `a`, `b` bound the bodies' motion from t0 on. Never returns a time at which
/// the sampled gap is negative: an overshoot (bounds violated) is bisected back into [0, gap_max].
RefineResult refineContactTime(const PartGapsFunction& gaps, const std::vector<DistanceSample>& at_t0,
                               const MotionBound& a, const MotionBound& b, double t0, double t1,
                               double gap_max, int max_queries = 64);

/// The gaps of bodies a and b (states valid at t0 [s]) after exact free flight to t under
/// `gravity` [m/s^2]. `caches` (parts(a) x parts(b), row-major) seed the walks; they are copied.
PartGapsFunction flightGaps(const RigidBody& a, const BodyShape& shape_a, const RigidBody& b,
                            const BodyShape& shape_b, const std::vector<FeatureCache>& caches,
                            const Vec3& gravity, double t0);

}  // namespace vroc::native
