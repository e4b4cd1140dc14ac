// SPDX-License-Identifier: MIT
// The harness's own exact distance query, independent of every backend, so penetration and
// resting gaps are judged by one neutral ruler (docs/harness.md, "Neutral distance").
//   sphere-sphere: analytic; sphere-box/hull: exact point-to-polytope distance (face polygons);
//   polytope pairs: brute force over features when disjoint (vertex-face, edge-edge), and the
//   separating-axis minimum overlap (face normals and edge-pair crosses) when they overlap.
#pragma once

#include "vroc/core/math.h"
#include "vroc/core/scene.h"
#include "vroc/core/shape.h"

namespace vroc::harness {

/// [m] signed distance between two shapes placed in the world: > 0 the gap between them,
/// < 0 minus the penetration depth (the smallest translation that separates them).
/// Compounds give the minimum over their parts.
double signedDistance(const Shape& a, const Pose& pose_a, const Shape& b, const Pose& pose_b);

/// [m] signed distance from a world point to a shape (< 0 inside).
double pointSignedDistance(const Vec3& point, const Shape& shape, const Pose& pose);

/// [m] signed distance between two scene bodies at the given poses.
double bodyDistance(const Scene& scene, int a, const Pose& pose_a, int b, const Pose& pose_b);

}  // namespace vroc::harness
