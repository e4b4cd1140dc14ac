// SPDX-License-Identifier: MIT
#include "dynamics/newton_coulomb.h"

#include <cmath>

namespace vroc::native {
namespace {

double norm1(const Mat3& m) { return m.cwiseAbs().colwise().sum().maxCoeff(); }

// The collision matrix is symmetric positive semi-definite and 3 x 3: its inverse by cofactors and
// the exact 1-norm reciprocal condition number 1 / (|K|_1 |K^-1|_1) (what an LU's rcond() only
// estimates) cost a fraction of a pivoted LU. Returns false when K is singular or nearly so.
bool solveCollisionMatrix(const Mat3& k, const Vec3& rhs, Vec3& x) {
    Mat3 adj;
    adj(0, 0) = k(1, 1) * k(2, 2) - k(1, 2) * k(2, 1);
    adj(0, 1) = k(0, 2) * k(2, 1) - k(0, 1) * k(2, 2);
    adj(0, 2) = k(0, 1) * k(1, 2) - k(0, 2) * k(1, 1);
    adj(1, 0) = k(1, 2) * k(2, 0) - k(1, 0) * k(2, 2);
    adj(1, 1) = k(0, 0) * k(2, 2) - k(0, 2) * k(2, 0);
    adj(1, 2) = k(0, 2) * k(1, 0) - k(0, 0) * k(1, 2);
    adj(2, 0) = k(1, 0) * k(2, 1) - k(1, 1) * k(2, 0);
    adj(2, 1) = k(0, 1) * k(2, 0) - k(0, 0) * k(2, 1);
    adj(2, 2) = k(0, 0) * k(1, 1) - k(0, 1) * k(1, 0);
    const double det = k(0, 0) * adj(0, 0) + k(0, 1) * adj(1, 0) + k(0, 2) * adj(2, 0);
    if (!(std::abs(det) > 0.0) || !std::isfinite(det)) return false;
    const Mat3 inv = adj / det;
    if (!(1.0 / (norm1(k) * norm1(inv)) > 1e-12)) return false;
    x = inv * rhs;
    return x.allFinite();
}

}  // namespace

Mat3 collisionMatrix(const RigidBody& a, const RigidBody& b, const Vec3& p) {
    const Mat3 ra = skew(p - a.com);
    const Mat3 rb = skew(p - b.com);
    return (a.inv_mass + b.inv_mass) * Mat3::Identity() - ra * a.invInertiaWorld() * ra -
           rb * b.invInertiaWorld() * rb;
}

ImpulseResult newtonCoulombImpulse(const RigidBody& a, const RigidBody& b, const Vec3& p,
                                   const Vec3& n, double restitution, double friction) {
    ImpulseResult out;
    const Vec3 u = b.pointVelocity(p) - a.pointVelocity(p);
    const double un = u.dot(n);
    if (!(un < 0.0)) return out;
    const Mat3 k = collisionMatrix(a, b, p);
    const Vec3 ut = u - un * n;
    // Sticking: stop the slip and reverse the normal velocity with restitution.
    const Vec3 target = -(1.0 + restitution) * un * n - ut;
    Vec3 j;
    if (solveCollisionMatrix(k, target, j)) {
        const double jn = j.dot(n);
        if (jn >= 0.0 && (j - jn * n).norm() <= friction * jn) {
            out.impulse = j;
            return out;
        }
    } else {
        out.trouble = ImpulseTrouble::IllConditioned;
    }
    // Sliding: impulse along n - mu t (t the slip direction) with the normal row enforced.
    const double slip = ut.norm();
    const Vec3 dir = slip > 0.0 ? Vec3(n - friction * ut / slip) : n;
    double denom = n.dot(k * dir);
    Vec3 d = dir;
    if (!(denom > 0.0)) {   // friction pushes the normal response the wrong way: drop friction
        out.trouble = ImpulseTrouble::Degenerate;
        d = n;
        denom = n.dot(k * n);
        if (!(denom > 0.0)) return {Vec3::Zero(), ImpulseTrouble::Degenerate};
    }
    out.impulse = (-(1.0 + restitution) * un / denom) * d;
    return out;
}

}  // namespace vroc::native
