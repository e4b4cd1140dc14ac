// SPDX-License-Identifier: MIT
// Conversions between VROC's Eigen types and Bullet's (both double precision here).
#pragma once

#include <LinearMath/btTransform.h>

#include "vroc/core/math.h"

static_assert(sizeof(btScalar) == 8, "the Bullet backend needs Bullet in double precision (bullet-float64)");

namespace vroc::bullet {

inline btVector3 toBt(const Vec3& v) { return {v.x(), v.y(), v.z()}; }
inline btQuaternion toBt(const Quat& q) { return {q.x(), q.y(), q.z(), q.w()}; }
inline btTransform toBt(const Pose& p) { return btTransform(toBt(p.orientation), toBt(p.position)); }

inline Vec3 fromBt(const btVector3& v) { return {v.x(), v.y(), v.z()}; }
inline Quat fromBt(const btQuaternion& q) { return Quat(q.w(), q.x(), q.y(), q.z()); }
inline Pose fromBt(const btTransform& t) { return {fromBt(t.getOrigin()), fromBt(t.getRotation())}; }

}  // namespace vroc::bullet
