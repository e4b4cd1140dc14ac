// SPDX-License-Identifier: MIT
// Single-point impulse models: momentum conservation, restitution, Coulomb friction (Garwin's
// oblique impact in both the sticking and the sliding regime), and the 15x15 system against the
// 3x3 Schur complement it reduces to.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "dynamics/newton_coulomb.h"
#include "dynamics/vroc1995_impulse.h"
#include "native_test_scenes.h"

namespace vroc::native::test {
namespace {

struct Momenta {
    Vec3 linear, angular;   // angular about the world origin
};
Momenta momenta(const RigidBody& a, const RigidBody& b) {
    auto lin = [](const RigidBody& r) { return Vec3(r.velocity / r.inv_mass); };
    return {lin(a) + lin(b),
            a.com.cross(lin(a)) + a.angular_momentum + b.com.cross(lin(b)) + b.angular_momentum};
}

double kinetic(const RigidBody& r) {
    return 0.5 * r.velocity.squaredNorm() / r.inv_mass + 0.5 * r.angular_momentum.dot(r.angularVelocity());
}

// Applies the impulse of a model at p for a pair made to approach along n.
template <class Model>
void collide(RigidBody& a, RigidBody& b, const Vec3& p, const Vec3& n, Model model) {
    const ImpulseResult r = model(a, b, p, n);
    EXPECT_EQ(r.trouble, ImpulseTrouble::None);
    a.applyImpulse(-r.impulse, p);
    b.applyImpulse(r.impulse, p);
}

TEST(DynamicsResponse, Vroc1995ConservesMomentumOfVirtualPairs) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int collided = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        RigidBody a = randomBody(rng), b = randomBody(rng);
        const Vec3 p = 0.5 * (a.com + b.com) + 0.2 * Vec3(u(rng), u(rng), u(rng));
        const Vec3 n = (b.com - a.com).normalized();
        const double e = 0.5 * (1 + u(rng));
        const Momenta before = momenta(a, b);
        const Vec3 u_rel = b.pointVelocity(p) - a.pointVelocity(p);
        if (!(u_rel.dot(n) < 0)) continue;
        ++collided;
        collide(a, b, p, n, [&](auto& x, auto& y, auto& q, auto& m) { return vroc1995Impulse(x, y, q, m, e); });
        const Momenta after = momenta(a, b);
        const double scale_l = before.linear.norm() + 1e-300;
        EXPECT_LT((after.linear - before.linear).norm(), 1e-12 * std::max(1.0, scale_l)) << trial;
        EXPECT_LT((after.angular - before.angular).norm(), 1e-12 * std::max(1.0, before.angular.norm())) << trial;
        // The contact points' relative velocity is reversed and scaled by e (all components).
        const Vec3 u_after = b.pointVelocity(p) - a.pointVelocity(p);
        EXPECT_LT((u_after + e * u_rel).norm(), 1e-9 * (1 + u_rel.norm())) << trial;
    }
    EXPECT_GT(collided, 500);
}

TEST(DynamicsResponse, Vroc1995MatchesSchurComplementAndConservesEnergyWhenElastic) {
    std::mt19937_64 rng(11);
    for (int trial = 0; trial < 200; ++trial) {
        RigidBody a = randomBody(rng), b = randomBody(rng);
        const Vec3 p = 0.5 * (a.com + b.com);
        const ImpulseResult r0 = vroc1995PlasticImpulse(a, b, p);
        const Vec3 u = b.pointVelocity(p) - a.pointVelocity(p);
        const Vec3 schur = collisionMatrix(a, b, p).fullPivLu().solve(-u);
        EXPECT_LT((r0.impulse - schur).norm(), 1e-9 * (1 + schur.norm())) << trial;
        const double k0 = kinetic(a) + kinetic(b);
        if (!(u.dot((b.com - a.com).normalized()) < 0)) continue;
        collide(a, b, p, (b.com - a.com).normalized(),
                [&](auto& x, auto& y, auto& q, auto& m) { return vroc1995Impulse(x, y, q, m, 1.0); });
        EXPECT_NEAR(kinetic(a) + kinetic(b), k0, 1e-10 * k0) << trial;
    }
}

TEST(DynamicsResponse, Vroc1995AgainstStaticBodyLeavesItStill) {
    std::mt19937_64 rng(3);
    RigidBody wall = randomBody(rng, true);
    RigidBody ball = randomBody(rng);
    ball.velocity = Vec3(0, 0, -3);
    ball.angular_momentum.setZero();
    ball.refreshEnergy();
    const Vec3 p = ball.com - Vec3(0, 0, 0.1);
    collide(wall, ball, p, Vec3::UnitZ(),
            [&](auto& x, auto& y, auto& q, auto& m) { return vroc1995Impulse(x, y, q, m, 0.5); });
    EXPECT_TRUE(wall.velocity.isZero(0.0));
    EXPECT_NEAR((ball.pointVelocity(p)).z(), 1.5, 1e-12);
}

// A sphere of radius r hits a static floor (normal +z) with velocity (vx, 0, vz < 0), spin wy.
RigidBody sphereBody(double r, double m, const Vec3& v, const Vec3& w) {
    Body b;
    b.name = "s";
    b.shape = Shape::sphere(r);
    b.mass_properties = massProperties(b.shape, m);
    b.pose = at(Vec3(0, 0, r));
    b.linear_velocity = v;
    b.angular_velocity = w;
    return RigidBody::fromScene(b);
}

TEST(DynamicsResponse, NewtonCoulombGarwinSticking) {
    // Small slip: the impulse stays in the cone, the contact point stops (e_x = 0):
    // v_x' = v_x - (2/7) u with u the contact point's tangential velocity (alpha = 2/5).
    RigidBody floor;
    const double r = 0.1, e = 0.6, mu = 0.8;
    RigidBody s = sphereBody(r, 2.0, Vec3(1.0, 0, -4.0), Vec3(0, 5.0, 0));
    const Vec3 p(0, 0, 0);
    const double u = s.pointVelocity(p).x();
    const double vx = s.velocity.x();
    collide(floor, s, p, Vec3::UnitZ(),
            [&](auto& x, auto& y, auto& q, auto& n) { return newtonCoulombImpulse(x, y, q, n, e, mu); });
    EXPECT_NEAR(s.velocity.z(), e * 4.0, 1e-12);
    EXPECT_NEAR(s.velocity.x(), vx - 2.0 / 7.0 * u, 1e-12);
    EXPECT_NEAR(s.pointVelocity(p).x(), 0.0, 1e-12);
}

TEST(DynamicsResponse, NewtonCoulombGarwinSliding) {
    // Large slip: dv_x = -mu (1 + e) |v_z| sign(u).
    RigidBody floor;
    const double r = 0.1, e = 0.5, mu = 0.2;
    RigidBody s = sphereBody(r, 1.0, Vec3(5.0, 0, -2.0), Vec3::Zero());
    const Vec3 p(0, 0, 0);
    collide(floor, s, p, Vec3::UnitZ(),
            [&](auto& x, auto& y, auto& q, auto& n) { return newtonCoulombImpulse(x, y, q, n, e, mu); });
    EXPECT_NEAR(s.velocity.z(), 1.0, 1e-12);
    EXPECT_NEAR(s.velocity.x(), 5.0 - mu * (1 + e) * 2.0, 1e-12);
}

TEST(DynamicsResponse, NewtonCoulombConservesMomentumOfVirtualPairs) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int trial = 0; trial < 1000; ++trial) {
        RigidBody a = randomBody(rng), b = randomBody(rng);
        const Vec3 p = 0.5 * (a.com + b.com) + 0.2 * Vec3(u(rng), u(rng), u(rng));
        const Vec3 n = (b.com - a.com).normalized();
        const Momenta before = momenta(a, b);
        const double k0 = kinetic(a) + kinetic(b);
        const ImpulseResult r = newtonCoulombImpulse(a, b, p, n, 0.5, 0.5);
        a.applyImpulse(-r.impulse, p);
        b.applyImpulse(r.impulse, p);
        const Momenta after = momenta(a, b);
        EXPECT_LT((after.linear - before.linear).norm(), 1e-12 * std::max(1.0, before.linear.norm()));
        EXPECT_LT((after.angular - before.angular).norm(), 1e-12 * std::max(1.0, before.angular.norm()));
        EXPECT_LE(kinetic(a) + kinetic(b), k0 * (1 + 1e-12)) << "a collision never adds energy";
    }
}

}  // namespace
}  // namespace vroc::native::test
