// SPDX-License-Identifier: MIT
// A body whose centre of mass is away from its origin and whose inertia is not diagonal in the
// body axes: Bullet simulates the principal frame, the backend must report the scene's frame.
#include <gtest/gtest.h>

#include <cmath>

#include "test_scenes.h"

namespace vroc::test {
namespace {

double angleBetween(const Quat& a, const Quat& b) { return a.angularDistance(b); }

struct OffsetBody {
    Scene scene = emptyScene();
    Vec3 half{0.3, 0.1, 0.05};
    Quat rot_in_body = Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
    Vec3 centre{0.4, -0.2, 0.1};   // COM in the body frame
    Pose pose{Vec3(1, 2, 3), Quat(Eigen::AngleAxisd(1.1, Vec3(-1, 0.5, 2).normalized()))};
    double mass = 3.0;
    int index = 0;
    OffsetBody() {
        scene.gravity = Vec3::Zero();
        index = addHullCuboid(scene, "offset", half, mass, pose, rot_in_body, centre);
    }
};

TEST(BulletBodyFrame, PoseAtStartIsTheScenePose) {
    OffsetBody b;
    auto backend = makeBullet(b.scene);
    const BodyState s = backend->bodyState(b.index);
    EXPECT_LT((s.pose.position - b.pose.position).norm(), 1e-12);
    EXPECT_LT(angleBetween(s.pose.orientation, b.pose.orientation), 1e-12);
}

TEST(BulletBodyFrame, SpinAboutAPrincipalAxisKeepsTheOriginOnItsClosedFormPath) {
    OffsetBody b;
    // Spin about the body's second principal axis (constant: no precession), COM drifting.
    const Vec3 axis_world = b.pose.orientation * (b.rot_in_body * Vec3::UnitY());
    const Vec3 omega = 2.5 * axis_world, v = Vec3(0.3, -0.1, 0.2);
    b.scene.bodies[0].angular_velocity = omega;
    b.scene.bodies[0].linear_velocity = v;
    auto backend = makeBullet(b.scene);
    const Vec3 com0 = b.pose.apply(b.centre);
    for (int f = 1; f <= 120; ++f) {
        backend->stepFrame(b.scene.frame_dt);
        const double t = f * b.scene.frame_dt;
        const Quat q = (Quat(Eigen::AngleAxisd(omega.norm() * t, axis_world)) * b.pose.orientation).normalized();
        const Vec3 com = com0 + v * t;
        const Vec3 origin = com - q * b.centre;
        const BodyState s = backend->bodyState(b.index);
        ASSERT_LT((s.pose.position - origin).norm(), 1e-9) << "frame " << f;
        ASSERT_LT(angleBetween(s.pose.orientation, q), 1e-9) << "frame " << f;
        ASSERT_LT((s.linear_velocity - v).norm(), 1e-12);
        ASSERT_LT((s.angular_velocity - omega).norm(), 1e-9);
    }
}

TEST(BulletBodyFrame, SetBodyStateReadsBackExactly) {
    OffsetBody b;
    auto backend = makeBullet(b.scene);
    BodyState want;
    want.pose = Pose{Vec3(-1, 0.5, 2), Quat(Eigen::AngleAxisd(2.0, Vec3(0.3, -1, 0.2).normalized()))};
    want.linear_velocity = Vec3(1, 2, -3);
    want.angular_velocity = Vec3(0.1, -0.4, 0.9);
    backend->setBodyState(b.index, want);
    const BodyState s = backend->bodyState(b.index);
    EXPECT_LT((s.pose.position - want.pose.position).norm(), 1e-12);
    EXPECT_LT(angleBetween(s.pose.orientation, want.pose.orientation), 1e-12);
    EXPECT_LT((s.linear_velocity - want.linear_velocity).norm(), 1e-15);
    EXPECT_LT((s.angular_velocity - want.angular_velocity).norm(), 1e-15);
}

TEST(BulletBodyFrame, ApplyImpulseChangesVelocitiesByTheRigidBodyFormulas) {
    OffsetBody b;
    auto backend = makeBullet(b.scene);
    const BodyState before = backend->bodyState(b.index);
    const Vec3 J(0.4, -1.2, 2.0);
    const Vec3 com = b.pose.apply(b.centre);
    const Vec3 point = com + Vec3(0.2, 0.3, -0.1);
    backend->applyImpulse(b.index, J, point);
    const BodyState after = backend->bodyState(b.index);
    // Closed form: dv = J / m, dw = I_world^-1 (r x J), I_world = R I_body R^T.
    const Mat3 R = b.pose.orientation.toRotationMatrix();
    const Mat3 I_body = b.rot_in_body.toRotationMatrix() * cuboidInertia(b.half, b.mass) *
                        b.rot_in_body.toRotationMatrix().transpose();
    const Mat3 I_world = R * I_body * R.transpose();
    const Vec3 dw = I_world.inverse() * (point - com).cross(J);
    EXPECT_LT((after.linear_velocity - before.linear_velocity - J / b.mass).norm(), 1e-12);
    EXPECT_LT((after.angular_velocity - before.angular_velocity - dw).norm(), 1e-9 * dw.norm());
}

TEST(BulletBodyFrame, RealBodiesIgnoreSetStateAndImpulses) {
    Scene scene = emptyScene();
    const int floor = addFloor(scene);
    auto backend = makeBullet(scene);
    BodyState moved;
    moved.pose.position = Vec3(5, 5, 5);
    backend->setBodyState(floor, moved);
    backend->applyImpulse(floor, Vec3(0, 0, 100), Vec3::Zero());
    backend->stepFrame(scene.frame_dt);
    const BodyState s = backend->bodyState(floor);
    EXPECT_EQ(s.pose.position, Vec3(0, 0, -0.5));
    EXPECT_EQ(s.linear_velocity, Vec3::Zero());
}

}  // namespace
}  // namespace vroc::test
