// SPDX-License-Identifier: MIT
// Radial lens distortion of the display optics and its pre-warp (inverse). Points are in image
// coordinates normalised by the half image height, centred on the optical axis:
// (x_ndc * aspect, y_ndc), so the distortion is isotropic. The lens shows a screen point p at
// distort(p) = p (1 + k1 r^2 + k2 r^4); drawing a point at prewarp(q) makes it appear at q.
#pragma once

#include <Eigen/Core>

namespace vroc::hmd {

using Vec2 = Eigen::Vector2d;

class LensDistortion {
public:
    LensDistortion(double k1, double k2) : k1_(k1), k2_(k2) {}

    bool isIdentity() const { return k1_ == 0.0 && k2_ == 0.0; }
    Vec2 distort(const Vec2& p) const;
    /// Inverse of distort by Newton iteration on the radius (converges to 1e-15 relative);
    /// throws std::domain_error where the distortion folds (d r_d / d r <= 0 on the way).
    Vec2 prewarp(const Vec2& q) const;
    /// r (1 + k1 r^2 + k2 r^4) [-]
    double distortRadius(double r) const { const double r2 = r * r; return r * (1.0 + k1_ * r2 + k2_ * r2 * r2); }

private:
    double undistortRadius(double rd) const;
    double k1_;
    double k2_;
};

}  // namespace vroc::hmd
