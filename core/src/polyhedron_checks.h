// SPDX-License-Identifier: MIT
// Internal: structural and geometric validation of a ConvexPolyhedron.
#pragma once

#include <string>

#include "vroc/core/convex_polyhedron.h"

namespace vroc::detail {

/// Empty if `p` is a valid closed convex polyhedron, else a one-line reason. Checks: indices in
/// range; every directed edge used once and its reverse once (closed, consistently oriented);
/// Euler V - E + F = 2; unit normals; every face vertex on its plane within `tolerance` [m];
/// every vertex on the inner side of every face plane within `tolerance` (when V x F exceeds
/// `global_budget`: every vertex of each edge-neighbouring face, which on a closed genus-0 surface
/// implies it); every vertex on >= 3 faces.
std::string checkPolyhedron(const ConvexPolyhedron& p, double tolerance, double global_budget = 2e7);

/// Volume [m^3] and surface area [m^2] of a closed polyhedron with outward CCW faces.
struct VolumeArea {
    double volume = 0.0;
    double area = 0.0;
};
VolumeArea volumeAndArea(const ConvexPolyhedron& p);

}  // namespace vroc::detail
