// SPDX-License-Identifier: MIT
// Rotation vectors (axis * angle [rad]) <-> unit quaternions: the exponential and logarithm maps
// of SO(3), used by the predictors and velocity estimators.
#pragma once

#include "vroc/core/math.h"

namespace vroc::hmd {

/// Unit quaternion of the rotation by |v| [rad] about v / |v|. Exact near zero (Taylor series).
Quat quatFromRotationVector(const Vec3& v);
/// Rotation vector of q with angle in [0, pi] (the shorter of q and -q).
Vec3 rotationVectorFromQuat(const Quat& q);
/// [rad] angle between two unit vectors, accurate for small and large angles (atan2 form).
double angleBetween(const Vec3& a, const Vec3& b);

}  // namespace vroc::hmd
