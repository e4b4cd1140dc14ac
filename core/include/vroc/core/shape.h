// SPDX-License-Identifier: MIT
// Collision shapes as the scene defines them, in the owning body's frame. Meshes are turned into
// hulls or compounds of hulls by the scene loader, so backends see only these four kinds.
#pragma once

#include <memory>
#include <vector>

#include "vroc/core/convex_polyhedron.h"
#include "vroc/core/math.h"

namespace vroc {

struct ShapePart;

struct Shape {
    enum class Kind { Sphere, Box, Hull, Compound };

    Kind kind = Kind::Sphere;
    double radius = 0.0;                              ///< [m] Sphere: centred at the frame origin
    Vec3 half_extents = Vec3::Zero();                 ///< [m] Box: centred, axis-aligned in the frame
    std::shared_ptr<const ConvexPolyhedron> hull;     ///< Hull: shared, immutable
    std::vector<ShapePart> parts;                     ///< Compound: convex parts only (never nested)

    static Shape sphere(double radius);
    static Shape box(const Vec3& half_extents);
    static Shape convexHull(ConvexPolyhedron hull);
    static Shape compound(std::vector<ShapePart> parts);

    const char* kindName() const;
    /// [m] radius of a sphere about the frame origin that contains the whole shape.
    double boundingRadius() const;
};

/// One convex part of a compound, placed in the compound's frame.
struct ShapePart {
    Shape shape;   ///< Sphere, Box or Hull
    Pose pose;     ///< part frame -> compound (body) frame
};

}  // namespace vroc
