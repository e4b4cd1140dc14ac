// SPDX-License-Identifier: MIT
#include "vroc/hmd/rotation_vector.h"

#include <cmath>

namespace vroc::hmd {

Quat quatFromRotationVector(const Vec3& v) {
    const double angle = v.norm();
    const double half = 0.5 * angle;
    // sin(half)/angle, with its series below 1e-4 rad where the division loses digits.
    const double s = angle < 1e-4 ? 0.5 - angle * angle / 48.0 : std::sin(half) / angle;
    return Quat(std::cos(half), s * v.x(), s * v.y(), s * v.z()).normalized();
}

Vec3 rotationVectorFromQuat(const Quat& q_in) {
    Quat q = q_in.normalized();
    if (q.w() < 0) q.coeffs() = -q.coeffs();
    const Vec3 xyz = q.vec();
    const double s = xyz.norm();
    if (s < 1e-12) return 2.0 * xyz;   // angle ~ 2 s
    const double angle = 2.0 * std::atan2(s, q.w());
    return xyz * (angle / s);
}

double angleBetween(const Vec3& a, const Vec3& b) {
    return std::atan2(a.cross(b).norm(), a.dot(b));
}

}  // namespace vroc::hmd
