// SPDX-License-Identifier: MIT
// Axis-aligned bounding box used by the native broad phase and the motion bounds.
// World frame, metres. Closed intervals: boxes that only touch overlap.
#pragma once

#include "vroc/core/math.h"

namespace vroc::native {

struct Aabb {
    Vec3 lower = Vec3::Zero();   ///< [m] world, component-wise minimum corner
    Vec3 upper = Vec3::Zero();   ///< [m] world, component-wise maximum corner

    /// Closed-interval overlap on all three axes (touching counts).
    bool overlaps(const Aabb& other) const {
        for (int axis = 0; axis < 3; ++axis) {
            if (lower[axis] > other.upper[axis] || other.lower[axis] > upper[axis]) return false;
        }
        return true;
    }
    /// Grown by `margin` [m] on every side.
    Aabb inflated(double margin) const {
        return {lower - Vec3::Constant(margin), upper + Vec3::Constant(margin)};
    }
};

}  // namespace vroc::native
