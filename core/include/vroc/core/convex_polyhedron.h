// SPDX-License-Identifier: MIT
// A closed convex polyhedron with true polygonal faces (coplanar triangles merged).
// Coordinates are in the frame of the shape that owns it (body frame, or a compound part's frame).
#pragma once

#include <span>
#include <vector>

#include "vroc/core/math.h"

namespace vroc {

struct ConvexPolyhedron {
    std::vector<Vec3> vertices;               ///< [m] only hull vertices (no interior or mid-edge points)
    std::vector<std::vector<int>> faces;      ///< vertex indices, counter-clockwise seen from outside
    std::vector<Vec3> face_normals;           ///< unit outward normal per face
    std::vector<double> face_offsets;         ///< [m] plane: face_normals[i].dot(x) == face_offsets[i]

    /// Convex hull of the points (qhull), coplanar facets merged into polygons.
    /// Throws GeometryError for fewer than 4 points, non-finite points, or (nearly) coplanar input.
    /// Tolerances scale with the points' bounding-box diagonal L: facets within 1e-9 L of coplanar
    /// are merged; the result is checked planar and convex within 1e-8 L, and input points lie
    /// inside it within 1e-8 L. Vertices are exact input points, numbered in input order.
    static ConvexPolyhedron fromPoints(std::span<const Vec3> points);
    /// Axis-aligned box centred at the origin with the given half extents [m].
    static ConvexPolyhedron box(const Vec3& half_extents);

    int edgeCount() const;                    ///< number of undirected edges
    double boundingRadius() const;            ///< [m] max |v| over vertices (about the local origin)
};

}  // namespace vroc
