// SPDX-License-Identifier: MIT
// Exact penetration depth of two convex polyhedra by the separating axis test: the minimum
// translation distance (MTD) is the smallest overlap over the face normals of A and of B and the
// normals of the Minkowski difference's edge-edge faces (Gregorius, "The Separating Axis Test
// between Convex Polyhedra", GDC 2013: an edge pair is such a face when the arcs of the two edges
// on the Gauss maps cross). Overlap along any direction is at least the MTD, so the minimum over
// these axes is the MTD itself, to rounding: not MPR's estimate along a portal (which on two boxes
// 18 mm into each other reported a normal along which they overlap by 33 mm).
#pragma once

#include "geometry/convex_mesh.h"
#include "vroc/core/math.h"

namespace vroc::native {

/// Which axis gave the depth.
enum class SatAxis { FaceA, FaceB, EdgeEdge, None };

struct SatPenetration {
    double depth = 0.0;              ///< [m] the MTD; <= 0: some axis separates (or touches)
    Vec3 normal = Vec3::UnitX();     ///< unit, world, from A towards B: move B by depth * normal to touch
    Vec3 point_a = Vec3::Zero();     ///< [m] world: A's deepest point into B along the normal
    Vec3 point_b = Vec3::Zero();     ///< [m] world: B's deepest point into A (point_a - point_b = depth * normal)
    SatAxis axis = SatAxis::None;
    int feature_a = -1, feature_b = -1;   ///< face, or undirected edge (half-edge / 2), per body; -1: a vertex
};

/// Most edge pairs (edges of A x edges of B) for which the exact test is used: its edge loop is
/// quadratic (~3.5 ns a pair here: 1 us for two 8-vertex hulls, 28 us for two of 32, 0.5 ms for two
/// of 128). 2,048 covers two hulls of 16 vertices (42 edges each) and every box pair; beyond it the
/// caller falls back to MPR's estimate (proximity.cpp).
inline constexpr long kSatMaxEdgePairs = 2048;
inline bool satAffordable(const ConvexMesh& a, const ConvexMesh& b) {
    return static_cast<long>(a.edgeCount()) * b.edgeCount() <= kSatMaxEdgePairs;
}

/// The minimum translation distance of mesh a at pose_a and mesh b at pose_b. Ties within rounding
/// go to a face axis (a face patch is the better contact). Allocates nothing once warm.
SatPenetration satPenetration(const ConvexMesh& a, const Pose& pose_a, const ConvexMesh& b, const Pose& pose_b);

}  // namespace vroc::native
