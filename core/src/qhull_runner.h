// SPDX-License-Identifier: MIT
// Internal: the one place that talks to qhull's reentrant C library (libqhull_r). Keeps qhull's
// macros (qh, FORALLfacets, True/False...) out of every other translation unit.
#pragma once

#include <span>
#include <vector>

#include "vroc/core/math.h"

namespace vroc::detail {

/// One (possibly merged, non-triangular) facet as qhull reports it.
struct QhullFacet {
    std::vector<int> point_ids;   ///< indices into the input points, unordered
    Vec3 outward_normal;          ///< unit, qhull's hyperplane normal (points away from the hull)
};

/// Convex hull of `points` with qhull's pre-merging: facets whose centrum lies within
/// `merge_distance` [m, same units as the points] of a neighbour's plane are merged, so coplanar
/// triangles become one polygonal facet. qhull never prints (its error stream goes to memory)
/// and never exits; a qhull failure throws GeometryError carrying qhull's first error line.
std::vector<QhullFacet> runQhull(std::span<const Vec3> points, double merge_distance);

}  // namespace vroc::detail
