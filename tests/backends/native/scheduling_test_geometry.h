// SPDX-License-Identifier: MIT
// Test-only reference geometry for the scheduling tests: exact sphere/box distances by brute
// force (independent of the native narrow phase), ballistic trajectories with a constant spin,
// and a reference "first time the distance reaches a level" found by Lipschitz-safe dense
// sampling plus bisection. World frame, SI units.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <sstream>
#include <string>

#include "scheduling/time_of_contact.h"
#include "vroc/core/math.h"

namespace vroc::native::scheduling_testing {

/// A body flying a parabola with a constant world angular velocity (a spinning box keeps its
/// spin axis fixed in this test model, so the rotation angle is exactly |ω| t).
struct Trajectory {
    Vec3 c0 = Vec3::Zero();      ///< [m] COM at t = 0
    Vec3 v = Vec3::Zero();       ///< [m/s]
    Vec3 a = Vec3::Zero();       ///< [m/s²]
    Vec3 omega = Vec3::Zero();   ///< [rad/s] constant, world
    Quat q0 = Quat::Identity();

    Vec3 center(double t) const { return c0 + v * t + 0.5 * a * t * t; }
    Quat orientation(double t) const {
        const double angle = omega.norm() * t;
        if (angle == 0.0) return q0;
        return (Quat(Eigen::AngleAxisd(angle, omega.normalized())) * q0).normalized();
    }
    std::string describe() const {
        std::ostringstream s;
        s.precision(17);
        s << "{{" << c0.x() << ", " << c0.y() << ", " << c0.z() << "}, {" << v.x() << ", " << v.y()
          << ", " << v.z() << "}, {" << a.x() << ", " << a.y() << ", " << a.z() << "}, {"
          << omega.x() << ", " << omega.y() << ", " << omega.z() << "}, Quat(" << q0.w() << ", "
          << q0.x() << ", " << q0.y() << ", " << q0.z() << ")}";
        return s.str();
    }
};

/// A sphere (half_extents unused, radius > 0) or a box (radius 0, half_extents > 0).
struct TestShape {
    double radius = 0.0;
    Vec3 half_extents = Vec3::Zero();
    bool isSphere() const { return radius > 0.0; }
    double outerRadius() const { return isSphere() ? radius : half_extents.norm(); }
    double innerRadius() const { return isSphere() ? radius : half_extents.minCoeff(); }
};

inline Vec3 closestOnSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 ab = b - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return a + t * ab;
}

/// Closest points of segments p1q1 and p2q2 (Ericson, Real-Time Collision Detection 5.1.9).
inline void closestSegmentSegment(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2,
                                  Vec3& c1, Vec3& c2) {
    const Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
    const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
    double s = 0.0, t = 0.0;
    if (a <= 1e-300 && e <= 1e-300) {
        s = t = 0.0;
    } else if (a <= 1e-300) {
        t = std::clamp(f / e, 0.0, 1.0);
    } else {
        const double c = d1.dot(r);
        if (e <= 1e-300) {
            s = std::clamp(-c / a, 0.0, 1.0);
        } else {
            const double b = d1.dot(d2), denom = a * e - b * b;
            s = denom > 0.0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
            t = (b * s + f) / e;
            if (t < 0.0) { t = 0.0; s = std::clamp(-c / a, 0.0, 1.0); }
            else if (t > 1.0) { t = 1.0; s = std::clamp((b - c) / a, 0.0, 1.0); }
        }
    }
    c1 = p1 + d1 * s;
    c2 = p2 + d2 * t;
}

struct PosedBox {
    Vec3 center;
    Mat3 rot;    // columns: box axes in world
    Vec3 half;
    Vec3 corner(int i) const {
        const Vec3 s((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0);
        return center + rot * s.cwiseProduct(half);
    }
    Vec3 closestPoint(const Vec3& p) const {
        const Vec3 local = rot.transpose() * (p - center);
        return center + rot * local.cwiseMax(-half).cwiseMin(half);
    }
};

/// Separating-axis test with the 15 box axes: true when the boxes intersect (touching counts).
inline bool boxesOverlap(const PosedBox& x, const PosedBox& y) {
    std::array<Vec3, 15> axes;
    int n = 0;
    for (int i = 0; i < 3; ++i) axes[n++] = x.rot.col(i);
    for (int i = 0; i < 3; ++i) axes[n++] = y.rot.col(i);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) axes[n++] = x.rot.col(i).cross(y.rot.col(j));
    for (const Vec3& axis : axes) {
        if (axis.squaredNorm() < 1e-20) continue;
        auto project = [&](const PosedBox& b) {
            double r = 0.0;
            for (int k = 0; k < 3; ++k) r += b.half[k] * std::abs(axis.dot(b.rot.col(k)));
            return std::pair{axis.dot(b.center) - r, axis.dot(b.center) + r};
        };
        const auto [lo_x, hi_x] = project(x);
        const auto [lo_y, hi_y] = project(y);
        if (hi_x < lo_y || hi_y < lo_x) return false;
    }
    return true;
}

/// Exact distance of separated boxes: the minimum over vertex–box and edge–edge pairs.
/// Overlapping boxes return −1 (the tests only need "at or below the level").
inline DistanceSample boxBoxDistance(const PosedBox& x, const PosedBox& y) {
    DistanceSample out;
    if (boxesOverlap(x, y)) { out.distance = -1.0; return out; }
    double best = std::numeric_limits<double>::infinity();
    auto consider = [&](const Vec3& px, const Vec3& py) {
        const double d = (py - px).norm();
        if (d < best) { best = d; out.point_a = px; out.point_b = py; }
    };
    for (int i = 0; i < 8; ++i) consider(x.corner(i), y.closestPoint(x.corner(i)));
    for (int i = 0; i < 8; ++i) consider(x.closestPoint(y.corner(i)), y.corner(i));
    static constexpr int kEdges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                                          {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    for (const auto& ex : kEdges) {
        for (const auto& ey : kEdges) {
            Vec3 cx, cy;
            closestSegmentSegment(x.corner(ex[0]), x.corner(ex[1]), y.corner(ey[0]), y.corner(ey[1]), cx, cy);
            consider(cx, cy);
        }
    }
    out.distance = best;
    out.normal = best > 0.0 ? Vec3((out.point_b - out.point_a) / best) : Vec3::UnitX();
    return out;
}

/// Distance between two shapes on their trajectories at time t (spheres and boxes, any mix).
inline DistanceSample shapeDistance(const TestShape& sa, const Trajectory& ta, const TestShape& sb,
                                    const Trajectory& tb, double t) {
    const Vec3 ca = ta.center(t), cb = tb.center(t);
    DistanceSample out;
    if (sa.isSphere() && sb.isSphere()) {
        const Vec3 d = cb - ca;
        const double len = d.norm();
        out.normal = len > 0.0 ? Vec3(d / len) : Vec3::UnitX();
        out.distance = len - sa.radius - sb.radius;
        out.point_a = ca + sa.radius * out.normal;
        out.point_b = cb - sb.radius * out.normal;
        return out;
    }
    if (sa.isSphere() != sb.isSphere()) {
        const bool a_is_sphere = sa.isSphere();
        const TestShape& sphere = a_is_sphere ? sa : sb;
        const TestShape& box = a_is_sphere ? sb : sa;
        const Trajectory& tbox = a_is_sphere ? tb : ta;
        const Vec3 centre = a_is_sphere ? ca : cb;
        const PosedBox pb{tbox.center(t), tbox.orientation(t).toRotationMatrix(), box.half_extents};
        const Vec3 on_box = pb.closestPoint(centre);
        const Vec3 d = centre - on_box;
        const double len = d.norm();
        if (len == 0.0) { out.distance = -1.0; return out; }   // centre inside the box
        const Vec3 box_to_sphere = d / len;
        out.distance = len - sphere.radius;
        const Vec3 on_sphere = centre - sphere.radius * box_to_sphere;
        out.point_a = a_is_sphere ? on_sphere : on_box;
        out.point_b = a_is_sphere ? on_box : on_sphere;
        out.normal = a_is_sphere ? Vec3(-box_to_sphere) : box_to_sphere;
        return out;
    }
    const PosedBox pa{ca, ta.orientation(t).toRotationMatrix(), sa.half_extents};
    const PosedBox pb{cb, tb.orientation(t).toRotationMatrix(), sb.half_extents};
    return boxBoxDistance(pa, pb);
}

/// First time in [t0, t1] at which f(t) <= level + epsilon, by sampling with steps that a
/// Lipschitz constant `lipschitz` [m/s] proves cannot skip a crossing (step = (f − level) / L,
/// at most max_step), with bisection if a sample lands below the level. The answer is never later
/// than the true first crossing and within epsilon / |f'| of it. +inf if none; NaN if
/// `max_samples` ran out (the caller skips such a case).
inline double firstCrossing(const std::function<double(double)>& f, double t0, double t1,
                            double level, double lipschitz, double max_step,
                            double epsilon = 1e-12, long max_samples = 2'000'000) {
    double t = t0;
    double ft = f(t);
    for (long n = 0; n < max_samples; ++n) {
        if (ft <= level + epsilon) return t;
        if (t >= t1) return std::numeric_limits<double>::infinity();
        const double step = std::min(max_step, (ft - level) / lipschitz);
        const double next = std::min(t + step, t1);
        const double fn = f(next);
        if (fn <= level) {   // only by rounding: bisect the last step
            double lo = t, hi = next;
            for (int i = 0; i < 200 && hi > lo; ++i) {
                const double mid = 0.5 * (lo + hi);
                if (mid <= lo || mid >= hi) break;
                (f(mid) <= level ? hi : lo) = mid;
            }
            return lo;
        }
        t = next;
        ft = fn;
    }
    return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace vroc::native::scheduling_testing
