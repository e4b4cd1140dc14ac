// SPDX-License-Identifier: MIT
// The real model of scenes/staircase.json in closed form, as an independent check of contact in
// play tests: six solid steps (step k: x in [0.3 k, 0.3 k + 0.3], y in [-0.5, 0.5], z in
// [0, 1.08 - 0.18 k]; scenes/meshes/staircase.obj) on a floor whose top is z = 0.
#pragma once

#include <algorithm>
#include <cmath>

#include "vroc/core/math.h"

namespace vroc::test {

/// [m] distance from p to an axis-aligned box (0 inside).
inline double distanceToBox(const Vec3& p, const Vec3& lo, const Vec3& hi) {
    return (lo - p).cwiseMax(p - hi).cwiseMax(Vec3::Zero()).norm();
}

/// [m] distance from p to the staircase and its floor (0 inside either).
inline double staircaseDistance(const Vec3& p) {
    double d = distanceToBox(p, Vec3(-2.5, -2.0, -0.2), Vec3(5.5, 2.0, 0.0));
    for (int k = 0; k < 6; ++k)
        d = std::min(d, distanceToBox(p, Vec3(0.3 * k, -0.5, 0.0), Vec3(0.3 * k + 0.3, 0.5, 1.08 - 0.18 * k)));
    return d;
}

}  // namespace vroc::test
