// SPDX-License-Identifier: MIT
#include "dynamics/free_flight.h"

#include <algorithm>
#include <cmath>

namespace vroc::native {
namespace {

using Vec4 = Eigen::Vector4d;

// [rad] largest orientation change the energy projection may make (RK4 errors are far smaller).
constexpr double kMaxEnergyCorrection = 1e-6;   // quaternion coefficients (x, y, z, w), Eigen's storage order

Quat toQuat(const Vec4& c) { return Quat(c(3), c(0), c(1), c(2)); }

// dq/dt = 1/2 (0, omega) * q with omega = R I^-1 R^T L evaluated at the normalised q.
Vec4 derivative(const Vec4& c, const Mat3& inv_inertia_body, const Vec3& angular_momentum) {
    const Quat q = toQuat(c).normalized();
    const Vec3 w = q * (inv_inertia_body * (q.conjugate() * angular_momentum));
    const Quat dq = Quat(0.0, w.x(), w.y(), w.z()) * toQuat(c);
    return 0.5 * dq.coeffs();
}

double energyOf(const Vec3& body_momentum, const Mat3& inv_inertia_body) {
    return 0.5 * body_momentum.dot(inv_inertia_body * body_momentum);
}

// Moves the body-frame momentum c = R^T L along the sphere |c| = const onto the energy level E0 and
// returns the body-frame rotation S with S p = c, so that R S maps p to L.
Quat energyCorrection(const Vec3& c, const Mat3& inv_inertia_body, double target_energy) {
    const double c2 = c.squaredNorm();
    if (c2 <= 0.0) return Quat::Identity();
    const Vec3 g = inv_inertia_body * c;
    const Vec3 gt = g - (g.dot(c) / c2) * c;        // energy gradient along the sphere
    const double slope = gt.squaredNorm();
    // Near a principal axis (or for an isotropic body) the energy is stationary along the sphere:
    // nothing to correct, and the gradient left is rounding noise (scale-free test: |gt| vs |g|).
    if (slope <= 1e-20 * g.squaredNorm()) return Quat::Identity();
    const double radius = std::sqrt(c2);
    Vec3 p = c;
    double lambda = 0.0;
    for (int it = 0; it < 3; ++it) {
        const double err = energyOf(p, inv_inertia_body) - target_energy;
        if (err == 0.0) break;
        lambda -= err / slope;
        p = (c + lambda * gt).normalized() * radius;
    }
    // The correction only removes integration error: a large one means the Newton step was
    // not meaningful (energy nearly stationary), so leave the orientation as integrated.
    const Quat s = Quat::FromTwoVectors(p, c);
    return s.angularDistance(Quat::Identity()) < kMaxEnergyCorrection ? s : Quat::Identity();
}

}  // namespace

double torqueFreeSpeedBound(const Vec3& moments, double l_squared, double twice_energy) {
    if (!(moments(0) > 0.0) || !(twice_energy > 0.0)) return -1.0;
    // Rounding in the invariants may leave an end's zero coordinate a little negative: accepted
    // within 1e-12 of the largest any x_i can be (2E / I_min: their rounding is ~1e-16 of that), and
    // covered by the margin.
    const double slack = 1e-12 * twice_energy / moments(0);
    double most = -1.0;
    for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j) {
            const double ii = moments(i), ij = moments(j);
            // Equal moments act as one axis: another pair (or isotropy) covers them.
            if (!(ij - ii > 1e-12 * ij)) continue;
            const double xi = (l_squared - twice_energy * ij) / (ii * (ii - ij));
            const double xj = (l_squared - twice_energy * ii) / (ij * (ij - ii));
            if (!(xi >= -slack) || !(xj >= -slack)) continue;
            most = std::max(most, std::max(0.0, xi) + std::max(0.0, xj));
        }
    return most < 0.0 ? -1.0 : std::sqrt(most + 2.0 * slack);
}

void advanceBallistic(RigidBody& body, double h, const Vec3& gravity) {
    if (body.is_static) return;
    if (body.is_kinematic) {   // prescribed motion: no gravity
        body.com += body.velocity * h;
        return;
    }
    body.com += body.velocity * h + (0.5 * h * h) * gravity;
    body.velocity += gravity * h;
}

int advanceTorqueFree(RigidBody& body, double h) {
    if (body.is_static || h <= 0.0) return 0;
    const double wmax = body.maxAngularSpeed();
    if (wmax == 0.0) return 0;
    if (body.isotropic) {
        // ω = I⁻¹ L is constant: the rotation over h is exactly the angle |ω| h about ω.
        const Vec3 w = body.angularVelocity();
        const double speed = w.norm();
        if (!(speed > 0.0)) return 0;
        const Eigen::AngleAxisd turn(speed * h, w / speed);
        body.orientation = (Quat(turn) * body.orientation).normalized();
        body.refreshAngularVelocity();
        return 1;
    }
    const int n = std::max(1, static_cast<int>(std::ceil(wmax * h / kMaxSubstepAngle)));
    const double s = h / n;
    const Mat3& ib = body.inv_inertia_body;
    const Vec3& l = body.angular_momentum;
    Vec4 c = body.orientation.coeffs();
    for (int i = 0; i < n; ++i) {
        const Vec4 k1 = derivative(c, ib, l);
        const Vec4 k2 = derivative(c + 0.5 * s * k1, ib, l);
        const Vec4 k3 = derivative(c + 0.5 * s * k2, ib, l);
        const Vec4 k4 = derivative(c + s * k3, ib, l);
        c += (s / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        c.normalize();
    }
    Quat q = toQuat(c);
    const Vec3 body_momentum = q.conjugate() * l;
    q = (q * energyCorrection(body_momentum, ib, body.rotational_energy)).normalized();
    body.orientation = q;
    body.refreshAngularVelocity();
    return n;
}

}  // namespace vroc::native
