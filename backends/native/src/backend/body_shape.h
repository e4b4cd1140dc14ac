// SPDX-License-Identifier: MIT
// A body's collision geometry for the native backend: convex parts (exact spheres or half-edge
// meshes) placed in the scene body frame, plus the radii the motion bounds need.
#pragma once

#include <memory>
#include <vector>

#include "geometry/convex_mesh.h"
#include "scheduling/aabb.h"
#include "scheduling/vertex_approach_bound.h"
#include "vroc/core/scene.h"

namespace vroc::native {

struct ConvexPart {
    bool is_sphere = false;
    double radius = 0.0;                          ///< [m] sphere radius
    std::shared_ptr<const ConvexMesh> mesh;       ///< polyhedra: shared, immutable
    Pose local;                                   ///< part frame -> scene body frame
    Vec3 bound_center = Vec3::Zero();             ///< [m] centre of a ball holding the part, scene body frame
    double bound_radius = 0.0;                    ///< [m] its radius
    double frame_radius = 0.0;                    ///< [m] |bound_center| + bound_radius: the part lies within it of the frame origin
    Vec3 box_lower = Vec3::Zero();                ///< [m] the part's box in its own frame
    Vec3 box_upper = Vec3::Zero();
    /// [m] A lower bound on the distance from the part (at `world`: part frame -> world) to a ball
    /// of `radius` about `center` (world): the ball against the part's own box.
    double gapToBall(const Pose& world, const Vec3& center, double radius) const;

    /// The part's support points at `world` (part frame -> world): a polytope's vertices, or a
    /// sphere's centre padded by its radius.
    SupportPoints supportPoints(const Pose& world) const;
};

struct BodyShape {
    std::vector<ConvexPart> parts;
    double outer_radius = 0.0;   ///< [m] R: farthest surface point from the COM
    double inner_radius = 0.0;   ///< [m] r: largest COM-centred ball inside (0 if unknown)
    /// [m] How thick the body is where a contact patch holds it: inner_radius for one part; for a
    /// compound (its COM may lie outside every part: inner_radius 0), its thinnest part's largest
    /// ball about the part's own centre. It scales the speculative reach on the grid.
    double reach_radius = 0.0;

    /// Builds the parts; `com` [m] is the COM in the body frame.
    static BodyShape fromScene(const Shape& shape, const Vec3& com);
    /// Exact world box of the shape at `frame` (body frame -> world).
    Aabb worldAabb(const Pose& frame) const;
};

}  // namespace vroc::native
