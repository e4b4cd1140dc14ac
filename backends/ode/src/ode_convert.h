// SPDX-License-Identifier: MIT
// Conversions between VROC's Eigen types and ODE's arrays (both double precision here).
// ODE quaternions are (w, x, y, z); Eigen's constructor takes the same order.
#pragma once

#include <ode/ode.h>

#include "vroc/core/math.h"

namespace vroc::ode {

inline Vec3 fromOde(const dReal* v) { return {v[0], v[1], v[2]}; }
inline Quat quatFromOde(const dReal* q) { return Quat(q[0], q[1], q[2], q[3]); }
inline void toOde(const Quat& q, dQuaternion out) {
    out[0] = q.w();
    out[1] = q.x();
    out[2] = q.y();
    out[3] = q.z();
}

}  // namespace vroc::ode
