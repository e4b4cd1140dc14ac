// SPDX-License-Identifier: MIT
// Penetration depth and direction from libccd's MPR (Minkowski Portal Refinement).
// Why MPR and not the walk's own answer: V-Clip's penetration verdict names a feature pair (an
// edge through a face, or a vertex inside every face plane), not a depth or a direction. Why
// MPR and not libccd's GJK+EPA: libccd#25 shows EPA returning depth 0 with a NaN direction on
// two overlapping cubes where MPR is right. The support mapping hill-climbs the half-edge mesh
// from the last support vertex, so a coherent call costs O(1) per support, not O(n).
#pragma once

#include "geometry/convex_mesh.h"
#include "vroc/core/math.h"

namespace vroc::native {

struct MprResult {
    bool intersecting = false;    ///< false: MPR found the shapes apart (touching within tolerance)
    double depth = 0.0;           ///< [m] >= 0, translate B by depth * direction to make them touch
    Vec3 direction = Vec3::UnitX();   ///< unit, world, from A towards B
    Vec3 position = Vec3::Zero(); ///< [m] world, between the two surfaces
};

/// World-frame MPR between mesh a at pose_a and mesh b at pose_b.
/// `hint_a`, `hint_b`: vertices to start the support hill climbs from (e.g. the cached features).
MprResult mprPenetration(const ConvexMesh& a, const Pose& pose_a, const ConvexMesh& b, const Pose& pose_b,
                         int hint_a = 0, int hint_b = 0);

}  // namespace vroc::native
