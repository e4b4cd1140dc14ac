// SPDX-License-Identifier: MIT
// A convex polytope in world coordinates with its edges listed, for the neutral distance query.
#pragma once

#include <utility>
#include <vector>

#include "vroc/core/math.h"
#include "vroc/core/shape.h"

namespace vroc::harness {

struct WorldPolytope {
    std::vector<Vec3> vertices;               ///< [m] world frame
    std::vector<std::vector<int>> faces;      ///< counter-clockwise seen from outside
    std::vector<Vec3> normals;                ///< unit outward, world frame
    std::vector<double> offsets;              ///< [m] normals[f].dot(x) == offsets[f] on face f
    std::vector<std::pair<int, int>> edges;   ///< undirected, each once
};

/// Box or Hull shape placed by `pose` (part pose already composed).
WorldPolytope placePolytope(const Shape& shape, const Pose& pose);

/// [m] distance from p to the polygon of face f (p anywhere).
double pointFaceDistance(const Vec3& p, const WorldPolytope& poly, std::size_t f);
/// [m] signed distance from p to the polytope (< 0 inside, exact).
double pointPolytopeDistance(const Vec3& p, const WorldPolytope& poly);
/// [m] distance between segments [p0, p1] and [q0, q1].
double segmentDistance(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1);
/// [m] signed distance between two polytopes (SAT depth when overlapping, brute force when not).
double polytopeDistance(const WorldPolytope& a, const WorldPolytope& b);

}  // namespace vroc::harness
