// SPDX-License-Identifier: MIT
// What every loaded shape and its mass properties must satisfy, checked independently of the
// loader's own checks (core/src/polyhedron_checks.*): a violation traps (fuzz_require.h).
#pragma once

#include "vroc/core/convex_polyhedron.h"
#include "vroc/core/mass_properties.h"
#include "vroc/core/shape.h"

namespace vroc::fuzz {

/// The contract of ConvexPolyhedron::fromPoints (convex_polyhedron.h): finite vertices inside
/// +-max_abs [m], at least 4 of them; faces of >= 3 valid indices forming a closed, consistently
/// oriented genus-0 surface (every directed edge once, V - E + F = 2); unit normals; every
/// vertex on or inside every face plane and every face vertex on its plane, within 1e-8 of the
/// bounding-box diagonal (the documented tolerance, with a little room for this check's rounding).
void checkPolyhedron(const ConvexPolyhedron& hull, double max_abs);

/// Unit quaternion (|q| within 1e-12 of 1) and finite position within +-max_abs [m].
void checkPose(const Pose& pose, double max_abs);

/// A loaded shape: sphere radius and box half extents in [1e-6, 1e6] m, hull as checkPolyhedron
/// with points inside +-1e6 m, compound of at least one non-compound part with valid poses
/// (docs/scene-format.md, "Accepted ranges").
void checkShape(const Shape& shape);

/// Properties of a body of `mass` [kg]: that mass, positive finite volume, finite centre of mass,
/// a symmetric inertia whose principal moments are positive and satisfy the triangle inequality
/// (as every rigid body's do), each within rounding of the largest moment.
void checkMassProperties(const MassProperties& props, double mass);

}  // namespace vroc::fuzz
