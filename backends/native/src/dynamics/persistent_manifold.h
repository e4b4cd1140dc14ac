// SPDX-License-Identifier: MIT
// PersistentManifold: a touching part pair's contact points and the impulses the contact solver
// accumulated on them, kept from one solve to the next so the next solve starts warm (Catto 2005;
// Bullet's btPersistentManifold, Box2D v3 manifold ids). The narrow phase refreshes the points at
// every solve from the cached closest features (the coherent walk); this cache only carries the
// impulses over. A new point takes the impulse of the cached point it coincides with in body A's
// frame (within `match_radius`): the patch points are the clip polygon's vertices, i.e. feature
// points of the two faces, so a persisting feature pair gives a coinciding point.
// Owned by the backend's pair state, one per part pair; plain data.
#pragma once

#include <span>
#include <vector>

#include "dynamics/contact.h"
#include "vroc/core/math.h"

namespace vroc::native {

/// Largest number of points a part pair's manifold keeps (Bullet, Box2D, Jolt: 4).
inline constexpr std::size_t kMaxManifoldPoints = 4;

struct PersistentManifold {
    std::vector<Vec3> local_a;            ///< [m] points in A's scene body frame
    std::vector<double> normal_impulse;   ///< [N s] accumulated normal impulse per point
    Vec3 tangent_impulse = Vec3::Zero();  ///< [N s] patch friction impulse, world
    double torsion_impulse = 0.0;         ///< [N m s] patch spin friction impulse
    double step = 0.0;                    ///< [s] step the impulses were solved for (0: empty)
    bool empty() const { return !(step > 0.0); }
    /// Empties the cache, keeping its storage (a pair's cache is refilled at every solve).
    void clear() {
        local_a.clear();
        normal_impulse.clear();
        tangent_impulse = Vec3::Zero();
        torsion_impulse = 0.0;
        step = 0.0;
    }
};

/// At most kMaxManifoldPoints of a convex patch polygon (CCW about `normal`, world): the point
/// farthest from the centroid, the point farthest from it, the one spanning the largest triangle
/// with those two, then the one adding the most area. Order of the input is kept (still CCW).
std::vector<Vec3> reduceContactPoints(const std::vector<Vec3>& points, const Vec3& normal);
/// The same choice as indices into `points` (ascending), so data kept per point follows it. With
/// `gaps` (one per point), the first point kept is the deepest instead of the farthest from the centroid.
/// Allocates nothing.
InlineVector<std::size_t, kMaxManifoldPoints> reduceContactPointIndices(std::span<const Vec3> points,
                                                                        const Vec3& normal,
                                                                        std::span<const double> gaps = {});

/// Fills m.point_impulse, m.tangent_impulse and m.torsion_impulse from the cache for a solve of
/// `step` [s] (impulses scale with the step, up by at most 3x: a resting load needs m g h). `frame_a` is body A's
/// scene frame -> world. Points without a match start at zero.
void warmStartManifold(const PersistentManifold& cache, const Pose& frame_a, double step,
                       double match_radius, ContactManifold& m);

/// Stores the solved manifold's points and impulses for the next solve.
void storeManifold(PersistentManifold& cache, const Pose& frame_a, double step, const ContactManifold& m);

}  // namespace vroc::native
