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
    /// [m] per point: the separation of the two pieces there along the normal (B's surface minus
    /// A's). Equal to the closest distance for parallel faces; larger at the far end of a tilted
    /// face that a speculative tolerance let in. Filled only for speculative contact (a reach).
    std::vector<double> gaps;
    Vec3 centroid = Vec3::Zero(); ///< area centroid of the polygon (segment midpoint, the point)
};

/// The patch of meshes a and b at their poses, touching as `result` (with the features in `cache`)
/// says. `tolerance` [m] decides "parallel" and "touching": a feature within it of the support plane
/// belongs to the patch (a speculative tolerance lets in what may close within a step).
///
/// With `reach` [m] above `tolerance` (speculative contact), the patch is instead the overlap of the
/// two faces at the closest features best aligned with the normal (the reference and incident faces
/// of Box2D's manifolds), and keeps the points whose gap is at most `reach`: a box landing on a
/// corner gets the other corners of its lower face as speculative points. If nothing is kept (the
/// faces do not overlap: crossed edges), the patch is as without `reach`.
ContactPatch contactPatch(const ConvexMesh& a, const Pose& pose_a, const ConvexMesh& b,
                          const Pose& pose_b, const FeatureCache& cache,
                          const ProximityResult& result, double tolerance, double reach = 0.0);
/// The same, into `patch` (cleared first; its storage is kept, so a caller that reuses one patch
/// allocates nothing once warm).
void contactPatch(const ConvexMesh& a, const Pose& pose_a, const ConvexMesh& b, const Pose& pose_b,
                  const FeatureCache& cache, const ProximityResult& result, double tolerance, double reach,
                  ContactPatch& patch);

}  // namespace vroc::native
