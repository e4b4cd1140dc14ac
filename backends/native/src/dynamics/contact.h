// SPDX-License-Identifier: MIT
// One touching pair of convex parts, as the response models see it.
#pragma once

#include "memory/inline_vector.h"
#include "vroc/core/math.h"

namespace vroc::native {

/// Most points a manifold carries: four that touch and, in the speculative regime, four more.
inline constexpr std::size_t kMaxManifoldSlots = 8;
/// A manifold's per-point data, stored in place: manifolds are built, copied and solved at every
/// internal step, and an allocation per copy was most of the step's heap traffic.
template <typename T>
using PointArray = InlineVector<T, kMaxManifoldSlots>;

struct ContactManifold {
    int body_a = -1;                  ///< index into the backend's bodies (a < b)
    int body_b = -1;
    int pair = -1;                    ///< index of the body pair (events aggregate by it)
    Vec3 normal = Vec3::UnitZ();      ///< unit, from A towards B, world
    double distance = 0.0;            ///< [m] signed gap of the closest features
    Vec3 centroid = Vec3::Zero();     ///< [m] single-point models: the patch centroid, world
    PointArray<Vec3> points;          ///< [m] manifold: the patch polygon (>= 1 point), world
    /// [m] per point of `points`: its separation along the normal (empty: every point at
    /// `distance`). A point beyond the collision distance is speculative: the contact phase lets it
    /// close to the speculative target within the step, and holds it there.
    PointArray<double> point_gap;
    double restitution = 0.0;         ///< [-] combined (minimum)
    double friction = 0.0;            ///< [-] combined (geometric mean)
    double collision_impulse = 0.0;   ///< [N s] normal impulse of the collision phase (output)
    double contact_impulse = 0.0;     ///< [N s] normal impulse of the contact phase (output)

    // Warm start (persistent manifolds, docs/native-dynamics.md): the previous solve's accumulated
    // impulses, carried over by the pair's manifold cache. Input to the contact phase, then its output.
    PointArray<double> point_impulse;    ///< [N s] per point of `points` (empty: cold start)
    Vec3 tangent_impulse = Vec3::Zero(); ///< [N s] patch friction impulse, world
    double torsion_impulse = 0.0;        ///< [N m s] patch spin friction impulse about the normal
};

}  // namespace vroc::native
