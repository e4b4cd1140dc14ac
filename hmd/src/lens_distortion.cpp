// SPDX-License-Identifier: MIT
#include "vroc/hmd/lens_distortion.h"

#include <cmath>
#include <stdexcept>

namespace vroc::hmd {

Vec2 LensDistortion::distort(const Vec2& p) const {
    const double r2 = p.squaredNorm();
    return p * (1.0 + k1_ * r2 + k2_ * r2 * r2);
}

double LensDistortion::undistortRadius(double rd) const {
    double r = rd;   // start at the undistorted guess: Newton then converges quadratically
    for (int i = 0; i < 50; ++i) {
        const double r2 = r * r;
        const double f = r * (1.0 + k1_ * r2 + k2_ * r2 * r2) - rd;
        const double df = 1.0 + 3.0 * k1_ * r2 + 5.0 * k2_ * r2 * r2;
        if (df <= 0.0) throw std::domain_error("lens distortion folds before this radius");
        const double step = f / df;
        r -= step;
        if (std::abs(step) <= 1e-16 * (1.0 + std::abs(r))) break;
    }
    return r;
}

Vec2 LensDistortion::prewarp(const Vec2& q) const {
    const double rd = q.norm();
    if (rd == 0.0 || isIdentity()) return q;
    return q * (undistortRadius(rd) / rd);
}

}  // namespace vroc::hmd
