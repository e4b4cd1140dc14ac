// SPDX-License-Identifier: MIT
#include "dynamics/newton_coulomb.h"

#include <Eigen/LU>

namespace vroc::native {

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
    Eigen::FullPivLU<Mat3> lu(k);
    if (lu.rcond() > 1e-12) {
        const Vec3 j = lu.solve(target);
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
