// SPDX-License-Identifier: MIT
// The rigid map from one body's local frame to another's: x_to = R x_from + t. The walk keeps
// each feature in its own mesh's frame and moves only the few points it compares (why: meshes
// stay immutable and shared, and a coherent query touches O(1) points).
#pragma once

#include "vroc/core/math.h"

namespace vroc::native {

struct RelativeFrame {
    Mat3 rotation = Mat3::Identity();   ///< from-frame axes expressed in the to-frame
    Vec3 translation = Vec3::Zero();    ///< [m] from-frame origin in the to-frame

    Vec3 apply(const Vec3& x) const { return rotation * x + translation; }
    Vec3 rotate(const Vec3& v) const { return rotation * v; }

    /// Maps B-local to A-local given both world poses.
    static RelativeFrame between(const Pose& to, const Pose& from) {
        const Mat3 rt = to.orientation.toRotationMatrix().transpose();
        return {rt * from.orientation.toRotationMatrix(), rt * (from.position - to.position)};
    }
    RelativeFrame inverse() const {
        const Mat3 rt = rotation.transpose();
        return {rt, -(rt * translation)};
    }
};

}  // namespace vroc::native
