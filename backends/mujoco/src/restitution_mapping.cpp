// SPDX-License-Identifier: MIT
#include "restitution_mapping.h"

#include <algorithm>
#include <cmath>

namespace vroc::mujoco {
namespace {

// Normalised contact (w = 1, entry speed 1): x'' = -2 zeta x' - x, x = penetration depth.
struct Phase {
    double x, v;
};

Phase derivative(const Phase& s, double zeta) { return {s.v, -2.0 * zeta * s.v - s.x}; }

Phase rk4(const Phase& s, double zeta, double h) {
    const Phase k1 = derivative(s, zeta);
    const Phase k2 = derivative({s.x + 0.5 * h * k1.x, s.v + 0.5 * h * k1.v}, zeta);
    const Phase k3 = derivative({s.x + 0.5 * h * k2.x, s.v + 0.5 * h * k2.v}, zeta);
    const Phase k4 = derivative({s.x + h * k3.x, s.v + h * k3.v}, zeta);
    return {s.x + h / 6.0 * (k1.x + 2 * k2.x + 2 * k3.x + k4.x), s.v + h / 6.0 * (k1.v + 2 * k2.v + 2 * k3.v + k4.v)};
}

// Pushing force (per unit mass) of the spring-damper at a phase point.
double force(const Phase& s, double zeta) { return s.x + 2.0 * zeta * s.v; }

}  // namespace

double releaseRestitution(double zeta) {
    // RK4 at a normalised step of 1e-3 (error ~1e-12) until the force crosses zero; the crossing
    // inside that step is found by bisection on the length of a single RK4 step from its start.
    const double h = 1e-3;
    Phase s{0.0, 1.0};
    for (int i = 0; i < 1000000; ++i) {
        const Phase next = rk4(s, zeta, h);
        if (i > 0 && force(next, zeta) <= 0.0) {
            double lo = 0.0, hi = h;   // force > 0 after lo, <= 0 after hi
            for (int k = 0; k < 60; ++k) {
                const double mid = 0.5 * (lo + hi);
                (force(rk4(s, zeta, mid), zeta) > 0.0 ? lo : hi) = mid;
            }
            return std::max(0.0, -rk4(s, zeta, 0.5 * (lo + hi)).v);
        }
        s = next;
    }
    return 0.0;   // not reached for zeta >= 0
}

double dampingRatioFor(double e, double zeta_max) {
    if (e >= 1.0) return 0.0;
    if (e <= releaseRestitution(zeta_max)) return zeta_max;
    double lo = 0.0, hi = zeta_max;   // releaseRestitution(lo) > e > releaseRestitution(hi)
    while (hi - lo > 1e-10) {
        const double mid = 0.5 * (lo + hi);
        (releaseRestitution(mid) > e ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

ContactSpring contactSpring(double e, double timeconst, double max_step) {
    const double w = 1.0 / timeconst;
    const double zeta_max = 1.0 / (2.0 * w * max_step);   // B h = 2 zeta w h <= 1
    const double zeta = dampingRatioFor(e, zeta_max);
    return {w * w, 2.0 * zeta * w};
}

}  // namespace vroc::mujoco
