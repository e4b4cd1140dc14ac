// SPDX-License-Identifier: MIT
// Contact region of a touching pair, from the closest features a proximity query found
// (proximity.h): what the contact solver spreads a pair's contact points over.
#pragma once

#include <vector>

#include "narrowphase/proximity.h"
#include "vroc/core/math.h"

namespace vroc::native {

/// A single point for vertex/edge contacts, the overlap polygon of two (nearly) parallel faces, or
/// the clipped segment of an edge on a face. Points are world, mid-way between the surfaces.
struct ContactPatch {
    std::vector<Vec3> points;     ///< polygon (CCW about normal) or segment or single point
    Vec3 centroid = Vec3::Zero(); ///< area centroid of the polygon (segment midpoint, the point)
};

/// The patch of meshes a and b at their poses, touching as `result` (with the features in `cache`)
/// says. `tolerance` [m] decides "parallel" and "touching".
ContactPatch contactPatch(const ConvexMesh& a, const Pose& pose_a, const ConvexMesh& b,
                          const Pose& pose_b, const FeatureCache& cache,
                          const ProximityResult& result, double tolerance);

}  // namespace vroc::native
