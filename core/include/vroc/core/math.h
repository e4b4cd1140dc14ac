// SPDX-License-Identifier: MIT
// Basic math types for VROC, on Eigen. All quantities SI: metres, kilograms, seconds, radians.
// Frames are right-handed. Quaternions are Eigen's (w, x, y, z internally); files use [x, y, z, w].
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace vroc {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;

/// A rigid transform: x_parent = orientation * x_local + position.
struct Pose {
    Vec3 position = Vec3::Zero();           ///< [m] origin of the local frame in the parent frame
    Quat orientation = Quat::Identity();    ///< unit quaternion, local -> parent

    static Pose identity() { return {}; }
    Vec3 apply(const Vec3& local) const { return orientation * local + position; }
    Vec3 applyInverse(const Vec3& parent) const { return orientation.conjugate() * (parent - position); }
    Vec3 rotate(const Vec3& v) const { return orientation * v; }
    /// Composition: (this * other).apply(x) == this->apply(other.apply(x)).
    Pose operator*(const Pose& other) const {
        return {orientation * other.position + position, (orientation * other.orientation).normalized()};
    }
    Pose inverse() const {
        Quat qi = orientation.conjugate();
        return {-(qi * position), qi};
    }
};

/// Skew-symmetric cross-product matrix: skew(a) * b == a.cross(b).
inline Mat3 skew(const Vec3& a) {
    Mat3 m;
    m << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
    return m;
}

inline bool allFinite(const Vec3& v) { return v.allFinite(); }

}  // namespace vroc
