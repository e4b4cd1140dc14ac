// SPDX-License-Identifier: MIT
#include "scheduling/motion_bound.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vroc::native {

namespace {

// Range of x(s) = v s + ½ a s² over s in [0, h]: endpoints and the apex if it lies inside.
void parabolaRange(double v, double a, double h, double& lo, double& hi) {
    const double end = v * h + 0.5 * a * h * h;
    lo = std::min(0.0, end);
    hi = std::max(0.0, end);
    if (a != 0.0) {
        const double apex_t = -v / a;
        if (apex_t > 0.0 && apex_t < h) {
            const double apex = v * apex_t + 0.5 * a * apex_t * apex_t;
            lo = std::min(lo, apex);
            hi = std::max(hi, apex);
        }
    }
}

}  // namespace

MotionBound MotionBound::advanced(double dt) const {
    MotionBound out = *this;
    out.velocity = velocity + acceleration * dt;
    return out;
}

bool MotionBound::valid() const {
    if (!velocity.allFinite() || !acceleration.allFinite()) return false;
    if (!(angular_speed >= 0.0) || !std::isfinite(angular_speed)) return false;
    if (!(outer_radius >= 0.0) || !(inner_radius >= 0.0)) return false;
    if (std::isinf(outer_radius) && angular_speed != 0.0) return false;
    return !std::isnan(outer_radius) && !std::isnan(inner_radius);
}

double MotionBound::rotationMargin() const {
    return outer_radius - std::min(inner_radius, outer_radius);
}

double MotionBound::chordBound(double t) const {
    if (angular_speed == 0.0 || t <= 0.0) return 0.0;   // also avoids 0 * inf for unbounded shapes
    const double angle = std::min(angular_speed * t, std::numbers::pi);
    return 2.0 * outer_radius * std::sin(0.5 * angle);
}

double MotionBound::rotationApproach(double t) const {
    if (angular_speed == 0.0 || t <= 0.0) return 0.0;
    switch (rotation_term) {
        case RotationTerm::PaperMargin: return rotationMargin();
        case RotationTerm::RateOnly: return chordBound(t);
        case RotationTerm::Tightest: break;
    }
    return std::min(chordBound(t), rotationMargin());
}

double MotionBound::translationAlong(const Vec3& n, double t) const {
    return n.dot(velocity) * t + 0.5 * n.dot(acceleration) * t * t;
}

double MotionBound::approachBound(const Vec3& n, double t) const {
    return translationAlong(n, t) + rotationApproach(t);
}

double MotionBound::maxTranslation(double t) const {
    if (t <= 0.0) return 0.0;
    return velocity.norm() * t + 0.5 * acceleration.norm() * t * t;
}

double MotionBound::maxDisplacement(double t) const {
    return maxTranslation(t) + chordBound(t);
}

Aabb MotionBound::sweptAabb(const Aabb& at_start, double h) const {
    const double rotation = rotationApproach(std::max(h, 0.0));
    Aabb out = at_start;
    for (int axis = 0; axis < 3; ++axis) {
        double lo = 0.0;
        double hi = 0.0;
        parabolaRange(velocity[axis], acceleration[axis], std::max(h, 0.0), lo, hi);
        out.lower[axis] += lo - rotation;
        out.upper[axis] += hi + rotation;
    }
    return out;
}

}  // namespace vroc::native
