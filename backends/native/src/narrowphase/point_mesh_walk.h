// SPDX-License-Identifier: MIT
// Closest feature of a convex mesh to a point, walking the Voronoi regions from a cached
// feature (the sphere–mesh special case: exact, no tessellated sphere). Mesh-local frame.
#pragma once

#include "geometry/convex_mesh.h"
#include "narrowphase/proximity.h"

namespace vroc::native {

struct PointWalkResult {
    Feature feature;               ///< closest feature (inside: the face of largest signed distance)
    Vec3 closest = Vec3::Zero();   ///< [m] local, closest surface point
    double signed_distance = 0.0;  ///< [m] > 0 outside, <= 0 inside (then minus the depth)
    int steps = 0;                 ///< feature transitions
    bool converged = true;         ///< false: step bound hit, answer from the O(n) scan
};

PointWalkResult closestFeatureToPoint(const ConvexMesh& mesh, const Vec3& p, Feature start);

}  // namespace vroc::native
