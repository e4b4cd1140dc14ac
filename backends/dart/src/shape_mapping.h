// SPDX-License-Identifier: MIT
// vroc::Shape -> DART shapes. Spheres and boxes are DART's own (SphereShape, BoxShape; how FCL
// collides them is dart.primitive_shapes); a hull is a MeshShape of its faces cut into triangle
// fans (DART 6.12 has no convex-polyhedron shape: FCL collides the triangle surface, so a body
// wholly inside it feels nothing); a compound is one shape per part, all on the same BodyNode.
// Each shape comes with its pose in the frame the compound's parts are given in (shape frame ->
// body frame of the scene).
#pragma once

#include <dart/dynamics/Shape.hpp>
#include <memory>
#include <string>
#include <vector>

#include "vroc/core/shape.h"

namespace vroc::dart {

/// "" if DART can represent `shape`; otherwise what is wrong ("hull face 3 has 2 vertices", ...).
std::string unsupportedReason(const Shape& shape);

/// One DART shape of a body, placed in the scene body's frame.
struct PlacedShape {
    std::shared_ptr<::dart::dynamics::Shape> shape;
    Pose pose;  ///< DART shape frame -> scene body frame
};

/// The DART shapes of `shape` (one, or one per compound part). Needs unsupportedReason(shape) == "".
std::vector<PlacedShape> dartShapes(const Shape& shape);

}  // namespace vroc::dart
