// SPDX-License-Identifier: MIT
// Exact flight: ballistic translation against the closed form; torque-free rotation of an
// asymmetric box near its intermediate axis (Dzhanibekov) against Euler's equations integrated
// independently, with energy and world angular momentum conserved.
#include <gtest/gtest.h>

#include <cmath>

#include "dynamics/free_flight.h"
#include "native_test_scenes.h"

namespace vroc::native::test {
namespace {

TEST(DynamicsFreeFlight, BallisticMatchesClosedForm) {
    Scene s = bareScene();
    addMaterial(s, 0.5, 0.5);
    Body& b = s.bodies.emplace_back();
    b.name = "b";
    b.shape = Shape::sphere(0.1);
    b.mass_properties = massProperties(b.shape, 2.0);
    b.pose = at(Vec3(1, -2, 30));
    b.linear_velocity = Vec3(3, 4, 12);
    RigidBody rb = RigidBody::fromScene(b);
    const Vec3 g = s.gravity;
    double t = 0;
    for (int i = 0; i < 600; ++i) {
        const double h = (i % 3 == 0) ? 1.0 / 60 : 1.0 / 240;   // uneven steps on purpose
        advanceBallistic(rb, h, g);
        t += h;
        const Vec3 x = b.pose.position + b.linear_velocity * t + 0.5 * g * t * t;
        const Vec3 v = b.linear_velocity + g * t;
        ASSERT_LT((rb.com - x).norm(), 1e-12 * (1 + x.norm())) << "t=" << t;
        ASSERT_LT((rb.velocity - v).norm(), 1e-12 * (1 + v.norm())) << "t=" << t;
    }
}

// Body-frame Euler equations I w' = (I w) x w, RK4 with a tiny step: the independent reference.
Vec3 eulerReference(const Vec3& inertia_diag, Vec3 w, double t_end, double dt) {
    auto f = [&](const Vec3& x) {
        const Vec3 l = inertia_diag.cwiseProduct(x);
        return Vec3(l.cross(x).cwiseQuotient(inertia_diag));
    };
    const int n = static_cast<int>(std::round(t_end / dt));
    for (int i = 0; i < n; ++i) {
        const Vec3 k1 = f(w), k2 = f(w + 0.5 * dt * k1), k3 = f(w + 0.5 * dt * k2), k4 = f(w + dt * k3);
        w += dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    return w;
}

TEST(DynamicsFreeFlight, DzhanibekovBoxConservesEnergyAndMomentum) {
    Body b;
    b.name = "tbar";
    b.shape = Shape::box(Vec3(0.05, 0.2, 0.45));   // 0.1 x 0.4 x 0.9 m: y is the intermediate axis
    b.mass_properties = massProperties(b.shape, 3.0);
    b.pose = at(Vec3::Zero(), Quat(Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized())));
    const Vec3 w_body(1e-3, 6.0, 2e-3);   // spun near the intermediate axis
    b.angular_velocity = b.pose.orientation * w_body;
    RigidBody rb = RigidBody::fromScene(b);
    const Vec3 l0 = rb.angular_momentum;
    const double e0 = 0.5 * l0.dot(rb.angularVelocity());
    const Vec3 inertia = b.mass_properties.inertia.diagonal();
    bool flipped = false;
    const double dt = 1.0 / 60;
    for (int i = 1; i <= 600; ++i) {
        advanceTorqueFree(rb, dt);
        const Vec3 w = rb.angularVelocity();
        const Mat3 r = rb.rotation();
        const Vec3 l = r * b.mass_properties.inertia * r.transpose() * w;
        ASSERT_LT((l - l0).norm(), 1e-12 * l0.norm()) << "t=" << i * dt;
        const double e = 0.5 * l0.dot(w);
        ASSERT_LT(std::abs(e - e0), 1e-9 * e0) << "t=" << i * dt;
        if ((rb.orientation.conjugate() * w).y() < 0) flipped = true;
        if (i == 120) {   // t = 2 s: body-frame angular velocity against Euler's equations
            const Vec3 ref = eulerReference(inertia, w_body, 2.0, 1e-5);
            EXPECT_LT((rb.orientation.conjugate() * w - ref).norm(), 1e-6 * ref.norm());
        }
    }
    EXPECT_TRUE(flipped) << "the intermediate-axis spin must flip within 10 s";
}

TEST(DynamicsFreeFlight, StableAxisSpinStaysPut) {
    Body b;
    b.name = "box";
    b.shape = Shape::box(Vec3(0.05, 0.2, 0.45));
    b.mass_properties = massProperties(b.shape, 1.0);
    b.angular_velocity = Vec3(0, 0, 10.0);   // smallest moment: stable
    RigidBody rb = RigidBody::fromScene(b);
    for (int i = 0; i < 600; ++i) advanceTorqueFree(rb, 1.0 / 60);
    EXPECT_LT((rb.angularVelocity() - Vec3(0, 0, 10)).norm(), 1e-9);
    // Closed form: rotation angle 10 rad/s * 10 s about z.
    const Quat expected(Eigen::AngleAxisd(100.0, Vec3::UnitZ()));
    EXPECT_LT(rb.orientation.angularDistance(expected), 1e-8);
}

TEST(DynamicsFreeFlight, IsotropicBodiesRotateInClosedForm) {
    // Spheres and cubes: ω is constant, so the orientation after t is exp(ω t / 2) q0 (rotation by
    // |ω| t about ω), whatever the pieces the flight is split into.
    for (const Shape& shape : {Shape::sphere(0.05), Shape::box(Vec3(0.1, 0.1, 0.1))}) {
        Body b;
        b.name = "iso";
        b.shape = shape;
        b.mass_properties = massProperties(b.shape, 0.7);
        b.pose = at(Vec3::Zero(), Quat(Eigen::AngleAxisd(0.4, Vec3(3, -1, 2).normalized())));
        const Vec3 w(17.0, -40.0, 9.0);
        b.angular_velocity = w;
        RigidBody rb = RigidBody::fromScene(b);
        ASSERT_TRUE(rb.isotropic);
        double t = 0.0;
        for (int i = 1; i <= 300; ++i) {   // uneven pieces, 10.5 s in all
            const double h = (i % 3 == 0) ? 0.05 : 0.01;
            advanceTorqueFree(rb, h);
            t += h;
        }
        const Quat expected = Quat(Eigen::AngleAxisd(w.norm() * t, w.normalized())) * b.pose.orientation;
        EXPECT_LT(rb.orientation.angularDistance(expected), 1e-10) << "t=" << t;
        EXPECT_LT((rb.angularVelocity() - w).norm(), 1e-12 * w.norm());
    }
}

}  // namespace
}  // namespace vroc::native::test

namespace vroc::native::test {
namespace {

// The body's bound on |ω| in torque-free flight (maxAngularSpeed, torqueFreeSpeedBound) against
// Euler's equations integrated independently: never exceeded along the motion, and met (the
// polhode passes through the ends of the segment the bound takes the largest of). The old bound,
// |L| / I_min, is the ceiling it never passes.
TEST(DynamicsFreeFlight, SpeedBoundHoldsAndIsMetAlongTheMotion) {
    struct Case {
        Vec3 half_extents;
        Vec3 w_body;
    };
    const Case cases[] = {
        {Vec3(0.05, 0.2, 0.45), Vec3(1e-3, 6.0, 2e-3)},    // near the intermediate axis (Dzhanibekov)
        {Vec3(0.05, 0.2, 0.45), Vec3(4.0, 1.0, 0.5)},      // about the major axis, wobbling
        {Vec3(0.05, 0.2, 0.45), Vec3(0.3, 0.8, 9.0)},      // about the minor axis, wobbling
        {Vec3(0.01, 0.05, 0.1), Vec3(2.0, -7.0, 3.0)},     // a domino
        {Vec3(0.02, 0.02, 0.3), Vec3(5.0, 0.0, 1.0)},      // a symmetric rod
    };
    for (const Case& c : cases) {
        Body b;
        b.name = "box";
        b.shape = Shape::box(c.half_extents);
        b.mass_properties = massProperties(b.shape, 2.0);
        b.pose = at(Vec3::Zero(), Quat(Eigen::AngleAxisd(0.7, Vec3(3, -1, 2).normalized())));
        b.angular_velocity = b.pose.orientation * c.w_body;
        const RigidBody rb = RigidBody::fromScene(b);
        const double bound = rb.maxAngularSpeed();
        const double loose = rb.angular_momentum.norm() / rb.smallestMoment();
        EXPECT_LE(bound, loose) << c.w_body.transpose();
        // Euler's equations in the body frame (the box's axes are its principal axes), RK4 at 1e-4 s.
        const Vec3 inertia = b.mass_properties.inertia.diagonal();
        Vec3 w = c.w_body;
        double most = w.norm();
        for (int k = 0; k < 400; ++k) {   // 20 s in 50 ms pieces
            w = eulerReference(inertia, w, 0.05, 1e-4);
            most = std::max(most, w.norm());
        }
        EXPECT_LE(most, bound * (1.0 + 1e-9)) << c.w_body.transpose();
        EXPECT_GE(most, bound * (1.0 - 1e-3)) << c.w_body.transpose() << ": the bound is not met";
    }
}

TEST(DynamicsFreeFlight, SpeedBoundOfAMajorAxisSpinIsItsOwnSpeed) {
    // A thin rod spun about its major axis keeps |ω|: the bound is that, where |L| / I_min is
    // 1,250 times it (the rod of NativeTunnel.SpinningRodNeverPassesThinPost).
    Body b;
    b.name = "rod";
    b.shape = Shape::box(Vec3(0.5, 0.01, 0.01));
    b.mass_properties = massProperties(b.shape, 1.0);
    b.angular_velocity = Vec3(0, 0, 50.0);
    const RigidBody rb = RigidBody::fromScene(b);
    EXPECT_NEAR(rb.maxAngularSpeed(), 50.0, 1e-6);
    EXPECT_GT(rb.angular_momentum.norm() / rb.smallestMoment(), 1000.0 * 50.0);
}

}  // namespace
}  // namespace vroc::native::test
