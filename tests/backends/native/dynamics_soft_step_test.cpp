// SPDX-License-Identifier: MIT
// The soft regime's contact phase (solveSoftStep) on one tick, against closed forms: a box resting
// on the ground is held by exactly its weight; a box too far to reach the ground in the tick falls
// as the sub-steps integrate gravity; one that would pass through it stops at the target; a box
// running into a free one hands on its momentum exactly and the two do not overlap.
#include <gtest/gtest.h>

#include "dynamics/soft_step.h"
#include "native_test_scenes.h"

namespace vroc::native::test {
namespace {

constexpr double kH = 1.0 / 60.0;
const Vec3 kGravity(0.0, 0.0, -9.81);

RigidBody box(const Vec3& com, double mass, bool is_static = false) {
    Body b;
    b.name = "box";
    b.role = is_static ? BodyRole::Real : BodyRole::Virtual;
    b.shape = Shape::box(Vec3(0.25, 0.25, 0.25));
    if (!is_static) b.mass_properties = massProperties(b.shape, mass);
    b.pose = at(com);
    return RigidBody::fromScene(b);
}

// The four corners of a 0.5 m box's face at height z, as a manifold from `a` (below) to `b`, each
// point `gap` apart along +z; or, with normal x, the face between two boxes side by side.
ContactManifold face(int a, int b, const Vec3& centre, const Vec3& normal, double gap, double friction) {
    ContactManifold m;
    m.body_a = a;
    m.body_b = b;
    m.pair = 0;
    m.normal = normal;
    m.distance = gap;
    m.friction = friction;
    const Vec3 t1 = normal.unitOrthogonal(), t2 = normal.cross(t1);
    for (int k = 0; k < 4; ++k) {
        m.points.push_back(centre + 0.25 * ((k & 1) ? 1.0 : -1.0) * t1 + 0.25 * ((k & 2) ? 1.0 : -1.0) * t2);
        m.point_gap.push_back(gap);
    }
    m.centroid = centre;
    return m;
}

SoftStepSettings settings(double cd) {
    SoftStepSettings s;
    s.iterations = 4;
    s.target = 0.25 * cd;
    s.speculative_from = cd;
    s.correction_floor = -0.25 * cd;
    return s;
}

TEST(SoftStep, RestingBoxIsHeldByItsWeight) {
    // Ticks in a row, each warm started from the last (as the persistent manifolds do) and the box
    // moved as its drift would: the iterations converge to the weight, the box to rest.
    const double cd = 1e-3, mass = 2.0;
    std::vector<RigidBody> bodies = {box(Vec3(0, 0, -0.25), 0.0, true), box(Vec3(0, 0, 0.25 + 0.5 * cd), mass)};
    std::vector<ContactManifold> m = {face(0, 1, Vec3(0, 0, 0), Vec3::UnitZ(), 0.5 * cd, 0.5)};
    std::vector<BodyImpulse> out;
    const double z0 = bodies[1].com.z();
    for (int tick = 0; tick < 20; ++tick) {
        solveSoftStep(bodies, m, kH, kGravity, settings(cd), out);
        ASSERT_TRUE(out[1].supported && out[1].sub_stepped);
        bodies[1].com += out[1].mean_velocity * kH;
        bodies[1].velocity = out[1].end_velocity;
        bodies[1].setAngularVelocity(out[1].end_angular_velocity);
    }
    EXPECT_NEAR(m[0].contact_impulse, mass * 9.81 * kH, 1e-9 * mass * 9.81 * kH)
        << "the tick's normal impulse is the weight's";
    EXPECT_LT(out[1].end_velocity.norm(), 1e-9);
    EXPECT_LT(out[1].end_angular_velocity.norm(), 1e-9);
    // Held where it was placed: no sinking below it (it was inside the window, above the target).
    EXPECT_GT(bodies[1].com.z() - z0, -1e-6);
    double sum = 0.0;
    for (double p : m[0].point_impulse) sum += p;
    EXPECT_NEAR(sum, mass * 9.81 * kH, 1e-9 * mass * 9.81 * kH) << "the warm start carries the weight on";
}

TEST(SoftStep, BoxOutOfReachFallsAsTheSubStepsIntegrate) {
    const double cd = 1e-3, gap = 0.2, v0 = -1.0;
    std::vector<RigidBody> bodies = {box(Vec3(0, 0, -0.25), 0.0, true), box(Vec3(0, 0, 0.25 + gap), 1.0)};
    bodies[1].velocity = Vec3(0, 0, v0);
    std::vector<ContactManifold> m = {face(0, 1, Vec3(0, 0, 0), Vec3::UnitZ(), gap, 0.5)};
    std::vector<BodyImpulse> out;
    SoftStepSettings s = settings(cd);
    solveSoftStep(bodies, m, kH, kGravity, s, out);
    EXPECT_DOUBLE_EQ(m[0].contact_impulse, 0.0);
    // n sub-steps of symplectic Euler: v_k = v0 + k g hs, x moves by the sum of v_k hs.
    const int n = s.substeps;
    const double hs = kH / n;
    const double drop = v0 * kH - 9.81 * hs * hs * n * (n + 1) / 2.0;
    EXPECT_NEAR(out[1].mean_velocity.z() * kH, drop, 1e-14);
    EXPECT_NEAR(out[1].end_velocity.z(), v0 - 9.81 * kH, 1e-14);
}

TEST(SoftStep, BoxThatWouldPassTheGroundStopsAtTheTarget) {
    const double cd = 1e-3, gap = 0.02;
    for (int iterations : {4, 64}) {
        std::vector<RigidBody> bodies = {box(Vec3(0, 0, -0.25), 0.0, true), box(Vec3(0, 0, 0.25 + gap), 1.0)};
        bodies[1].velocity = Vec3(0, 0, -3.0);  // 12.5 mm per sub-step: arrives in the second
        std::vector<ContactManifold> m = {face(0, 1, Vec3(0, 0, 0), Vec3::UnitZ(), gap, 0.5)};
        std::vector<BodyImpulse> out;
        SoftStepSettings s = settings(cd);
        s.iterations = iterations;
        solveSoftStep(bodies, m, kH, kGravity, s, out);
        const double end_gap = gap + out[1].mean_velocity.z() * kH;
        // Never through the ground; with the iterations converged, exactly at the target.
        EXPECT_GT(end_gap, 0.0) << iterations << " iterations";
        if (iterations == 64) {
            EXPECT_NEAR(end_gap, s.target, 1e-9);
            EXPECT_NEAR(out[1].end_velocity.z(), 0.0, 1e-9);
            // The ground took the fall's momentum and the weight over the tick.
            EXPECT_NEAR(m[0].contact_impulse, 3.0 + 9.81 * kH, 1e-9);
        }
    }
}

TEST(SoftStep, ImpactOnAFreeBoxConservesMomentumWithoutOverlap) {
    // No gravity, no ground: A (1 kg) at 7 m/s, B (3 kg) at rest 1 cm ahead along x.
    const double cd = 1e-3, gap = 0.01;
    // (The iterations and the relaxations: one relaxation of a 4-point face, point by point, leaves
    // the patch's impulse lopsided and the boxes spinning; converged, they do not.)
    for (int iterations : {1, 64}) {
        std::vector<RigidBody> bodies = {box(Vec3(0, 0, 0), 1.0), box(Vec3(0.5 + gap, 0, 0), 3.0)};
        bodies[0].velocity = Vec3(7.0, 0, 0);
        std::vector<ContactManifold> m = {face(0, 1, Vec3(0.25, 0, 0), Vec3::UnitX(), gap, 0.3)};
        std::vector<BodyImpulse> out;
        SoftStepSettings s = settings(cd);
        s.iterations = s.relax_iterations = iterations;
        solveSoftStep(bodies, m, kH, Vec3::Zero(), s, out);
        const Vec3 p = 1.0 * out[0].end_velocity + 3.0 * out[1].end_velocity;
        EXPECT_NEAR((p - Vec3(7.0, 0, 0)).norm(), 0.0, 1e-12) << iterations << " iterations: momentum";
        const double closed = (out[0].mean_velocity.x() - out[1].mean_velocity.x()) * kH;
        EXPECT_LE(closed, gap - s.target + 1e-12) << iterations << " iterations: A may close to the target, no farther";
        if (iterations == 64) {
            // Inelastic (no restitution in the contact phase): both leave at 7/4, without spin.
            EXPECT_NEAR(out[0].end_velocity.x(), 1.75, 1e-9);
            EXPECT_NEAR(out[1].end_velocity.x(), 1.75, 1e-9);
            EXPECT_LT(out[0].end_angular_velocity.norm() + out[1].end_angular_velocity.norm(), 1e-9);
        }
    }
}

}  // namespace
}  // namespace vroc::native::test
