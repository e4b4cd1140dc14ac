// SPDX-License-Identifier: MIT
#include "dynamics/vroc1995_impulse.h"

#include <Eigen/LU>

#include "dynamics/newton_coulomb.h"

namespace vroc::native {

ImpulseResult vroc1995PlasticImpulse(const RigidBody& a, const RigidBody& b, const Vec3& p) {
    using Mat15 = Eigen::Matrix<double, 15, 15>;
    using Vec15 = Eigen::Matrix<double, 15, 1>;
    const Vec3 r1 = p - a.com;
    const Vec3 r2 = p - b.com;
    const Mat3 i1 = a.invInertiaWorld();
    const Mat3 i2 = b.invInertiaWorld();
    const Mat3 id = Mat3::Identity();
    // Inverse-mass form, so a static body (zero inverse mass) keeps its velocity exactly.
    Mat15 m = Mat15::Zero();
    Vec15 rhs = Vec15::Zero();
    m.block<3, 3>(0, 0) = id;   m.block<3, 3>(0, 12) = a.inv_mass * id;      // v1' + R/m1 = v1
    m.block<3, 3>(3, 3) = id;   m.block<3, 3>(3, 12) = -b.inv_mass * id;     // v2' - R/m2 = v2
    m.block<3, 3>(6, 6) = id;   m.block<3, 3>(6, 12) = i1 * skew(r1);        // w1' + I1^-1 r1 x R = w1
    m.block<3, 3>(9, 9) = id;   m.block<3, 3>(9, 12) = -i2 * skew(r2);       // w2' - I2^-1 r2 x R = w2
    // closure: v2' + w2' x r2 - v1' - w1' x r1 = 0  (w x r = -skew(r) w)
    m.block<3, 3>(12, 0) = -id;
    m.block<3, 3>(12, 3) = id;
    m.block<3, 3>(12, 6) = skew(r1);
    m.block<3, 3>(12, 9) = -skew(r2);
    rhs.segment<3>(0) = a.velocity;
    rhs.segment<3>(3) = b.velocity;
    rhs.segment<3>(6) = a.angularVelocity();
    rhs.segment<3>(9) = b.angularVelocity();
    Eigen::FullPivLU<Mat15> lu(m);
    ImpulseResult out;
    if (lu.rcond() > 1e-13) {
        out.impulse = lu.solve(rhs).segment<3>(12);
        if (out.impulse.allFinite()) return out;
    }
    // Recovery: the same impulse from the 3x3 Schur complement K R = -u.
    out.trouble = ImpulseTrouble::IllConditioned;
    const Vec3 u = b.pointVelocity(p) - a.pointVelocity(p);
    Eigen::FullPivLU<Mat3> k(collisionMatrix(a, b, p));
    out.impulse = k.isInvertible() ? Vec3(k.solve(-u)) : Vec3::Zero();
    if (!out.impulse.allFinite()) out.impulse = Vec3::Zero();
    return out;
}

ImpulseResult vroc1995Impulse(const RigidBody& a, const RigidBody& b, const Vec3& p, const Vec3& n,
                              double restitution) {
    const Vec3 u = b.pointVelocity(p) - a.pointVelocity(p);
    if (!(u.dot(n) < 0.0)) return {};
    ImpulseResult out = vroc1995PlasticImpulse(a, b, p);
    out.impulse *= (1.0 + restitution);
    return out;
}

}  // namespace vroc::native
