// SPDX-License-Identifier: MIT
// vroc::Shape -> btCollisionShape. Spheres and boxes are Bullet's implicit shapes (their margin
// lies inside, surfaces exact); hulls are btConvexHullShape (shrunk by the margin so faces stay
// where the scene puts them); compounds, and any shape whose Bullet frame is not the scene's
// body frame (centre of mass off the origin), become btCompoundShape.
#pragma once

#include <memory>
#include <vector>

#include "vroc/core/shape.h"

class btCollisionShape;

namespace vroc::bullet {

struct ShapeOptions {
    double margin = 0.04;        ///< [m] wanted margin for boxes and hulls
    bool shrink_hulls = true;    ///< shrink hull planes by the margin
};

/// [m] radius of a sphere that fits inside the shape around its centre (a compound: its largest
/// part's). Sizes the CCD swept sphere and motion threshold.
double innerRadius(const Shape& shape);

/// Builds Bullet shapes and owns them (and their children) until it is destroyed.
class ShapeMapper {
public:
    explicit ShapeMapper(ShapeOptions options);
    ~ShapeMapper();
    ShapeMapper(const ShapeMapper&) = delete;
    ShapeMapper& operator=(const ShapeMapper&) = delete;

    /// A Bullet shape for `shape`, expressed in the frame `frame` (frame -> scene body frame).
    /// The returned pointer stays owned by the mapper.
    btCollisionShape* map(const Shape& shape, const Pose& frame);

private:
    btCollisionShape* convex(const Shape& shape);
    btCollisionShape* hull(const ConvexPolyhedron& poly);
    btCollisionShape* keep(std::unique_ptr<btCollisionShape> shape);

    ShapeOptions options_;
    std::vector<std::unique_ptr<btCollisionShape>> owned_;
};

}  // namespace vroc::bullet
