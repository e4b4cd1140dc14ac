// SPDX-License-Identifier: MIT
// Exact closest points between the primitive pieces of convex features (point, segment, plane).
// Pure functions on whatever frame the caller uses; lengths in metres.
#pragma once

#include <algorithm>

#include "vroc/core/math.h"

namespace vroc::native {

/// Parameter t in [0, 1] of the point of segment a + t (b - a) closest to p.
inline double closestOnSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 d = b - a;
    const double dd = d.squaredNorm();
    if (dd <= 0.0) return 0.0;
    return std::clamp((p - a).dot(d) / dd, 0.0, 1.0);
}

/// Closest points of segments p0p1 and q0q1: returns (s, t) with points p0 + s (p1 - p0) and
/// q0 + t (q1 - q0). The interior solution (Ericson, RTCD 5.1.9) competes with the four
/// endpoint-to-segment candidates, so (nearly) parallel segments stay exact too.
struct SegmentParams {
    double s = 0.0;
    double t = 0.0;
};

inline SegmentParams closestSegmentSegment(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
    const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
    const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
    const double c = d1.dot(r), b = d1.dot(d2);
    const double denom = a * e - b * b;   // >= 0; 0 when parallel
    auto gap = [&](double s, double t) { return (p0 + s * d1 - q0 - t * d2).squaredNorm(); };
    SegmentParams best{0.0, closestOnSegment(p0, q0, q1)};
    double best_gap = gap(best.s, best.t);
    auto offer = [&](double s, double t) {
        const double g = gap(s, t);
        if (g < best_gap) {
            best_gap = g;
            best = {s, t};
        }
    };
    offer(1.0, closestOnSegment(p1, q0, q1));
    offer(closestOnSegment(q0, p0, p1), 0.0);
    offer(closestOnSegment(q1, p0, p1), 1.0);
    if (denom > 0.0 && a > 0.0 && e > 0.0) {
        double s = std::clamp((b * f - c * e) / denom, 0.0, 1.0);
        double t = std::clamp((b * s + f) / e, 0.0, 1.0);
        s = std::clamp((b * t - c) / a, 0.0, 1.0);
        offer(s, t);
    }
    return best;
}

}  // namespace vroc::native
