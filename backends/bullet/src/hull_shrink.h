// SPDX-License-Identifier: MIT
// Bullet's hulls carry a margin: the collision surface is the hull of the points grown by a
// sphere of radius `margin`. Shrinking every face plane inward by the margin first makes the
// grown surface's faces lie exactly on the scene's faces (only edges and corners are rounded).
#pragma once

#include <vector>

#include "vroc/core/convex_polyhedron.h"

namespace vroc::bullet {

/// [m] a margin no larger than `wanted` that leaves a non-degenerate shrunk hull: at most a
/// quarter of the smallest distance from the vertex centroid to a face plane.
double safeHullMargin(const ConvexPolyhedron& hull, double wanted);

/// Vertices of the hull with every face plane moved inward by `margin` [m]. Each shrunk vertex
/// is the meeting point of three face planes around an original vertex, kept only if it lies
/// inside every shrunk plane (so the shrunk hull never pokes out of the original).
/// Needs the face planes (faces, face_normals, face_offsets).
std::vector<Vec3> shrunkHullVertices(const ConvexPolyhedron& hull, double margin);

}  // namespace vroc::bullet
