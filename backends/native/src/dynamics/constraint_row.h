// SPDX-License-Identifier: MIT
// One velocity row of a contact constraint between two bodies, prepared once per solve: the moment
// arm of a unit impulse along a direction on each body and the spin it gives that body. A
// relaxation is then dot products and scaled additions, with no 3x3 product (the block solver's
// normal and friction rows, the soft step's rows).
#pragma once

#include "vroc/core/math.h"

namespace vroc::native {

struct ConstraintRow {
    Vec3 ra = Vec3::Zero(), rb = Vec3::Zero();   ///< r x d on A and on B: the row's moment arms
    Vec3 ia = Vec3::Zero(), ib = Vec3::Zero();   ///< I^-1 (r x d): the spin a unit impulse gives each body

    /// The row along `d` for contact arms `ra`, `rb` (point - COM, world) and world inverse inertias.
    static ConstraintRow along(const Vec3& ra, const Vec3& rb, const Vec3& d, const Mat3& inv_inertia_a,
                               const Mat3& inv_inertia_b) {
        ConstraintRow row;
        row.ra = ra.cross(d);
        row.rb = rb.cross(d);
        row.ia = inv_inertia_a * row.ra;
        row.ib = inv_inertia_b * row.rb;
        return row;
    }
};

}  // namespace vroc::native
