// SPDX-License-Identifier: MIT
// Rotation vectors (axis * angle [rad]) <-> unit quaternions: the exponential and logarithm maps of
// SO(3). Header-only on purpose: the predictors and velocity estimators (hmd, play) and the
// built-in device plugins (which link nothing of core) share this one definition.
#pragma once

#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace vroc {

/// Unit quaternion of the rotation by |v| [rad] about v / |v|. Exact near zero (Taylor series).
inline Eigen::Quaterniond quatFromRotationVector(const Eigen::Vector3d& v) {
    const double angle = v.norm();
    const double half = 0.5 * angle;
    // sin(half)/angle, with its series below 1e-4 rad where the division loses digits.
    const double s = angle < 1e-4 ? 0.5 - angle * angle / 48.0 : std::sin(half) / angle;
    return Eigen::Quaterniond(std::cos(half), s * v.x(), s * v.y(), s * v.z()).normalized();
}

/// Rotation vector of q with angle in [0, pi] (the shorter of q and -q).
inline Eigen::Vector3d rotationVectorFromQuat(const Eigen::Quaterniond& q_in) {
    Eigen::Quaterniond q = q_in.normalized();
    if (q.w() < 0) q.coeffs() = -q.coeffs();
    const Eigen::Vector3d xyz = q.vec();
    const double s = xyz.norm();
    if (s < 1e-12) return 2.0 * xyz;   // angle ~ 2 s
    const double angle = 2.0 * std::atan2(s, q.w());
    return xyz * (angle / s);
}

/// [rad] angle between two vectors, accurate for small and large angles (atan2 form).
inline double angleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return std::atan2(a.cross(b).norm(), a.dot(b));
}

}  // namespace vroc
