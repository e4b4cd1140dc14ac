// SPDX-License-Identifier: MIT
#include "scheduling/collision_time_bound.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace vroc::native {

namespace {

// Rotation term of one body as pieces: rot(t) = rate * t until t = switch_time, then margin
// (Tightest); or a single piece (RateOnly: rate * t, PaperMargin: margin from t > 0 on).
struct RotationPieces {
    double rate = 0.0;           // [m/s] |ω| R, used while t < switch_time
    double margin = 0.0;         // [m] R − r, used from switch_time on
    double switch_time = kNever; // [s]
};

RotationPieces rotationPieces(const MotionBound& m) {
    RotationPieces p;
    if (m.angular_speed == 0.0) return p;   // no rotation: rot(t) = 0 (avoids 0 * inf)
    const double rate = m.angular_speed * m.outer_radius;
    const double margin = m.rotationMargin();
    switch (m.rotation_term) {
        case RotationTerm::RateOnly: p.rate = rate; break;
        case RotationTerm::PaperMargin: p.margin = margin; p.switch_time = 0.0; break;
        case RotationTerm::Tightest:
            p.rate = rate;
            p.margin = margin;
            p.switch_time = rate > 0.0 ? margin / rate : kNever;
            break;
    }
    return p;
}

// Smallest t in [lo, hi] with q2 t² + q1 t + q0 >= 0, given that it is < 0 at lo; kNever if none.
// The returned root is pulled back by a few ulps so rounding never makes it late.
double firstNonNegative(double q2, double q1, double q0, double lo, double hi) {
    std::array<double, 2> roots{kNever, kNever};
    if (q2 == 0.0) {
        if (q1 > 0.0) roots[0] = -q0 / q1;
    } else {
        double disc = q1 * q1 - 4.0 * q2 * q0;
        // A tangent touch may come out slightly negative by rounding: treat it as a double root.
        if (disc < 0.0 && disc >= -1e-12 * (q1 * q1 + std::abs(4.0 * q2 * q0))) disc = 0.0;
        if (disc < 0.0) return kNever;
        // Stable form: q = -(q1 + sign(q1) sqrt(disc)) / 2, roots q/q2 and q0/q.
        const double s = std::sqrt(disc);
        const double q = -0.5 * (q1 + (q1 >= 0.0 ? s : -s));
        roots[0] = q / q2;
        roots[1] = q != 0.0 ? q0 / q : kNever;
    }
    double best = kNever;
    // f(lo) < 0, so the first root after lo is where f reaches 0 (a crossing or a touch). A root
    // rounded to just below lo still belongs to this piece.
    const double slack = 1e-12 * std::max(1.0, std::abs(lo));
    for (double r : roots) {
        if (r >= lo - slack && r <= hi) best = std::min(best, std::max(r, lo));
    }
    if (best == kNever) return kNever;
    return std::max(lo, best - 4.0 * std::numeric_limits<double>::epsilon() * std::abs(best));
}

// Earliest t in [0, horizon] with c1 t + c2 t² + rotA(t) + rotB(t) >= gap.
double solvePiecewise(double gap, double c1, double c2, const RotationPieces& ra,
                      const RotationPieces& rb, double horizon) {
    if (!(gap > 0.0)) return 0.0;
    if (!(horizon >= 0.0)) return kNever;
    std::array<double, 4> cuts{0.0, std::min(ra.switch_time, horizon),
                               std::min(rb.switch_time, horizon), horizon};
    std::sort(cuts.begin(), cuts.end());
    for (int i = 0; i + 1 < 4; ++i) {
        const double lo = cuts[i];
        const double hi = cuts[i + 1];
        if (!(hi > lo)) continue;   // empty piece: its end points belong to the neighbours
        // Each piece lies wholly on one side of each switch time, so one regime per body holds.
        const double mid = 0.5 * (lo + hi);
        const bool a_sat = mid >= ra.switch_time;
        const bool b_sat = mid >= rb.switch_time;
        const double q1 = c1 + (a_sat ? 0.0 : ra.rate) + (b_sat ? 0.0 : rb.rate);
        const double q0 = (a_sat ? ra.margin : 0.0) + (b_sat ? rb.margin : 0.0) - gap;
        if (c2 * lo * lo + q1 * lo + q0 >= 0.0) return lo;
        const double t = firstNonNegative(c2, q1, q0, lo, hi);
        if (t != kNever) return t;
    }
    return kNever;
}

}  // namespace

double earliestCollisionTime(double gap, const Vec3& normal_ab, const MotionBound& a,
                             const MotionBound& b, double horizon) {
    const double c1 = normal_ab.dot(a.velocity - b.velocity);
    const double c2 = 0.5 * normal_ab.dot(a.acceleration - b.acceleration);
    return solvePiecewise(gap, c1, c2, rotationPieces(a), rotationPieces(b), horizon);
}

double earliestCollisionTime(double gap, const MotionBound& a, const MotionBound& b,
                             double horizon) {
    const double c1 = (a.velocity - b.velocity).norm();
    const double c2 = 0.5 * (a.acceleration - b.acceleration).norm();
    return solvePiecewise(gap, c1, c2, rotationPieces(a), rotationPieces(b), horizon);
}

}  // namespace vroc::native
