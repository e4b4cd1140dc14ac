// SPDX-License-Identifier: MIT
#include "narrowphase/manifold_anchor.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vroc::native {

void anchorManifold(const ContactManifold& m, const Pose& fa, const Pose& fb, double window, ManifoldAnchor& out) {
    out.valid = true;
    out.relative = fa.inverse() * fb;
    out.window = window;
    out.distance = m.distance;
    out.normal_a = fa.orientation.conjugate() * m.normal;
    out.centroid_a = fa.applyInverse(m.centroid);
    out.on_a.clear();
    out.on_b.clear();
    out.gap.clear();
    for (const Vec3& p : m.points) {
        out.on_a.push_back(fa.applyInverse(p));
        out.on_b.push_back(fb.applyInverse(p));
    }
    for (double g : m.point_gap) out.gap.push_back(g);
}

double anchoredMotion(const ManifoldAnchor& anchor, const Pose& fa, const Pose& fb, double radius_a, double radius_b) {
    // In A's frame the motion maps y to turn * y + (p_now - turn * p_then).
    const Pose now = fa.inverse() * fb;
    const Quat turn = now.orientation * anchor.relative.orientation.conjugate();
    // Angle of the turn: 2 atan2(|v|, |w|) (sign-free, exact near zero).
    const double angle = 2.0 * std::atan2(turn.vec().norm(), std::abs(turn.w()));
    const double near_a = (now.position - turn * anchor.relative.position).norm() + angle * radius_a;
    const double near_b = (now.position - anchor.relative.position).norm() + angle * radius_b;
    return std::min(near_a, near_b);
}

bool carryManifold(const ManifoldAnchor& anchor, const Pose& fa, const Pose& fb, ContactManifold& m) {
    const Vec3 n = fa.rotate(anchor.normal_a);
    m.normal = n;
    m.centroid = fa.apply(anchor.centroid_a);
    m.points.clear();
    m.point_gap.clear();
    double least = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < anchor.on_a.size(); ++k) {
        const Vec3 xa = fa.apply(anchor.on_a[k]);
        const Vec3 xb = fb.apply(anchor.on_b[k]);
        const double change = n.dot(xb - xa);
        least = std::min(least, change);
        m.points.push_back(xa);
        if (k < anchor.gap.size()) m.point_gap.push_back(anchor.gap[k] + change);
    }
    m.distance = anchor.distance + least;
    return std::isfinite(m.distance) && m.distance >= 0.0 && m.distance < anchor.window;
}

}  // namespace vroc::native
