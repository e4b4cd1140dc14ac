// SPDX-License-Identifier: MIT
#include "scheduling/vertex_approach_bound.h"

#include <algorithm>
#include <cmath>

#include "scheduling/collision_time_bound.h"

namespace vroc::native {
namespace {

// A point's height along n as a quadratic bound: level + speed t + ½ accel t².
struct Height {
    double level;   // [m]
    double speed;   // [m/s]
    double accel;   // [m/s^2]
};

// Upper bounds on the points' heights along n (B's points are passed with -n).
std::vector<Height> heights(const SupportPoints& s, const RigidMotion& m, const Vec3& n) {
    std::vector<Height> out;
    out.reserve(s.points.size());
    const double n_accel = n.dot(m.acceleration);
    for (const Vec3& p : s.points) {
        const Vec3 rho = p - m.com;
        out.push_back({n.dot(p) + s.pad, n.dot(m.velocity + m.angular_velocity.cross(rho)),
                       n_accel + m.curvature * rho.norm()});
    }
    return out;
}

// [m] the most a height can rise over [0, h] (its bound's positive parts).
double maxRise(const Height& x, double h) { return std::max(0.0, x.speed) * h + 0.5 * std::max(0.0, x.accel) * h * h; }

// Rounding in the coefficients is far below this; the floors the callers use sit well above the
// depth at which penetration becomes an emergency.
constexpr double kPullBack = 1.0 - 1e-9;

}  // namespace

double firstReach(double slack, double speed, double accel) {
    if (accel == 0.0) return speed > 0.0 ? slack / speed : kNever;
    const double disc = speed * speed + 2.0 * accel * slack;
    if (disc < 0.0) return kNever;   // a decelerating approach that turns before the slack
    const double denom = speed + std::sqrt(disc);
    if (!(denom > 0.0)) return kNever;
    return 2.0 * slack / denom;
}

double rotationCurvatureBound(double angular_momentum, double torque, double smallest_moment, double duration,
                              bool isotropic) {
    const double l_max = angular_momentum + torque * std::max(0.0, duration);
    if (l_max == 0.0) return 0.0;
    if (!(smallest_moment > 0.0)) return kNever;
    const double omega = l_max / smallest_moment;
    const double spin_change = isotropic ? torque / smallest_moment : (torque + omega * l_max) / smallest_moment;
    return spin_change + omega * omega;
}

double vertexApproachTime(const SupportPoints& a, const RigidMotion& ma, const SupportPoints& b,
                          const RigidMotion& mb, const Vec3& normal_ab, double floor, double horizon) {
    if (a.points.empty() || b.points.empty() || !(horizon > 0.0)) return 0.0;
    if (!normal_ab.allFinite() || std::abs(normal_ab.squaredNorm() - 1.0) > 1e-9) return 0.0;
    const Vec3& n = normal_ab;
    const std::vector<Height> ha = heights(a, ma, n);    // A's points: upper bounds
    const std::vector<Height> hb = heights(b, mb, -n);   // B's points seen along -n: upper bounds
    // From here B's heights are measured along -n, so a pair's gap is -(hb.level) - ha.level.
    for (const Height& x : ha)
        if (!std::isfinite(x.level) || !std::isfinite(x.speed) || std::isnan(x.accel)) return 0.0;
    for (const Height& y : hb)
        if (!std::isfinite(y.level) || !std::isfinite(y.speed) || std::isnan(y.accel)) return 0.0;
    // Only points that can reach the other side's reach matter: a pair (i, j) can close below the
    // floor within the horizon only if A's i can rise above B's lowest reach (and vice versa).
    const double h = std::isfinite(horizon) ? horizon : 1e9;   // [s] finite, so 0 · h stays 0
    double reach_a = -kNever, reach_b = -kNever;   // highest reach of A along n, of B along -n
    double top_a = -kNever, top_b = -kNever;
    for (const Height& x : ha) {
        reach_a = std::max(reach_a, x.level + maxRise(x, h));
        top_a = std::max(top_a, x.level);
    }
    for (const Height& y : hb) {
        reach_b = std::max(reach_b, y.level + maxRise(y, h));
        top_b = std::max(top_b, y.level);
    }
    // σ(0) = -top_b - top_a.
    if (!(-top_b - top_a > floor)) return 0.0;
    double first = horizon;
    for (const Height& x : ha) {
        if (!(x.level + maxRise(x, h) + reach_b > -floor)) continue;
        for (const Height& y : hb) {
            if (!(y.level + maxRise(y, h) + reach_a > -floor)) continue;
            const double slack = -y.level - x.level - floor;
            const double t = firstReach(slack, x.speed + y.speed, x.accel + y.accel);
            first = std::min(first, t);
        }
    }
    return first >= horizon ? kNever : first * kPullBack;
}

}  // namespace vroc::native
