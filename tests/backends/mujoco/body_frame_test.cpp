// SPDX-License-Identifier: MIT
// Body frame vs centre of mass, MuJoCo's free-joint velocity convention, setBodyState round trips
// and applyImpulse, all against closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "test_scenes.h"

namespace vroc::test {
namespace {

// A hull cuboid whose COM is off the body origin and whose inertia is not diagonal in body axes.
Scene offsetHullScene(int& body) {
    Scene scene = emptyScene();
    scene.gravity = Vec3::Zero();
    Pose pose;
    pose.position = Vec3(0.3, -0.2, 1.5);
    pose.orientation = Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
    body = addHullCuboid(scene, "hull", Vec3(0.2, 0.1, 0.05), 3.0, pose,
                         Quat(Eigen::AngleAxisd(0.4, Vec3(0, 1, 1).normalized())), Vec3(0.05, 0.02, -0.03));
    return scene;
}

bool sameRotation(const Quat& a, const Quat& b, double tol) { return std::abs(std::abs(a.dot(b)) - 1.0) < tol; }

TEST(MujocoBodyFrame, InitialStateIsTheScenes) {
    int body = 0;
    Scene scene = offsetHullScene(body);
    scene.bodies[body].linear_velocity = Vec3(0.1, 0.2, -0.3);
    scene.bodies[body].angular_velocity = Vec3(1.0, -2.0, 0.5);
    auto backend = makeMujoco(scene);
    const BodyState s = backend->bodyState(body);
    EXPECT_LT((s.pose.position - scene.bodies[body].pose.position).norm(), 1e-12);
    EXPECT_TRUE(sameRotation(s.pose.orientation, scene.bodies[body].pose.orientation, 1e-12));
    EXPECT_LT((s.linear_velocity - scene.bodies[body].linear_velocity).norm(), 1e-12);
    EXPECT_LT((s.angular_velocity - scene.bodies[body].angular_velocity).norm(), 1e-12);
}

TEST(MujocoBodyFrame, SetBodyStateRoundTrips) {
    int body = 0;
    Scene scene = offsetHullScene(body);
    auto backend = makeMujoco(scene);
    BodyState in;
    in.pose.position = Vec3(-1.0, 2.0, 0.5);
    in.pose.orientation = Quat(Eigen::AngleAxisd(2.5, Vec3(-1, 0.5, 2).normalized()));
    if (in.pose.orientation.w() < 0) in.pose.orientation.coeffs() *= -1.0;
    in.linear_velocity = Vec3(3.0, -1.0, 0.25);
    in.angular_velocity = Vec3(-0.5, 4.0, 1.5);
    backend->setBodyState(body, in);
    const BodyState out = backend->bodyState(body);
    EXPECT_LT((out.pose.position - in.pose.position).norm(), 1e-12 * in.pose.position.norm());
    EXPECT_LT((out.pose.orientation.coeffs() - in.pose.orientation.coeffs()).norm(), 1e-12);
    EXPECT_LT((out.linear_velocity - in.linear_velocity).norm(), 1e-12 * in.linear_velocity.norm());
    EXPECT_LT((out.angular_velocity - in.angular_velocity).norm(), 1e-12 * in.angular_velocity.norm());
}

// The angular velocity is reported in the world frame whatever the body's orientation: a sphere
// (no gyroscopic torque) turned 90 degrees about x and spun about world z keeps (0, 0, w) and turns
// about world z by w t; its body x axis ends at (cos wt, sin wt, 0).
TEST(MujocoBodyFrame, AngularVelocityIsWorldFrame) {
    Scene scene = emptyScene();
    scene.gravity = Vec3::Zero();
    const int ball = addBall(scene, "ball", 0.1, 1.0, Vec3::Zero());
    scene.bodies[ball].pose.orientation = Quat(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitX()));
    const double w = 1.5;
    scene.bodies[ball].angular_velocity = Vec3(0, 0, w);
    auto backend = makeMujoco(scene);
    run(*backend, scene, 30);
    const BodyState s = backend->bodyState(ball);
    EXPECT_LT((s.angular_velocity - Vec3(0, 0, w)).norm(), 1e-12);
    const double angle = w * backend->time();
    const Vec3 x_axis = s.pose.orientation * Vec3::UnitX();
    EXPECT_LT((x_axis - Vec3(std::cos(angle), std::sin(angle), 0)).norm(), 1e-9) << x_axis.transpose();
    // The body's y axis was turned onto world z and stays there.
    EXPECT_LT((s.pose.orientation * Vec3::UnitY() - Vec3::UnitZ()).norm(), 1e-9);
}

// A spin about a principal axis through an off-origin COM: the COM stays put and the body origin
// circles it, origin(t) = com - q(t) c (c = COM in body coordinates).
TEST(MujocoBodyFrame, OffsetComStaysPutUnderSpin) {
    int body = 0;
    Scene scene = offsetHullScene(body);
    const Body& b = scene.bodies[body];
    // The hull's principal axes in world coordinates: its parts were rotated by rot_in_body.
    const Quat rot_in_body(Eigen::AngleAxisd(0.4, Vec3(0, 1, 1).normalized()));
    const Vec3 axis = b.pose.orientation * (rot_in_body * Vec3::UnitZ());
    scene.bodies[body].angular_velocity = 2.0 * axis;
    const Vec3 com0 = b.pose.apply(b.mass_properties.center_of_mass);
    auto backend = makeMujoco(scene);
    run(*backend, scene, 120);
    const BodyState s = backend->bodyState(body);
    const Vec3 com = s.pose.apply(scene.bodies[body].mass_properties.center_of_mass);
    EXPECT_LT((com - com0).norm(), 1e-12);
    EXPECT_LT((s.angular_velocity - 2.0 * axis).norm(), 1e-9);
}

TEST(MujocoBodyFrame, ApplyImpulseChangesMomentumExactly) {
    int body = 0;
    Scene scene = offsetHullScene(body);
    scene.bodies[body].linear_velocity = Vec3(0.3, 0.0, -0.1);
    scene.bodies[body].angular_velocity = Vec3(0.2, 0.1, -0.4);
    auto backend = makeMujoco(scene);
    const BodyState before = backend->bodyState(body);
    const Body& b = scene.bodies[body];
    const Vec3 J(0.7, -1.2, 2.0), p(0.5, 0.1, 1.4);
    backend->applyImpulse(body, J, p);
    const BodyState after = backend->bodyState(body);
    const double m = b.mass_properties.mass;
    EXPECT_LT((m * (after.linear_velocity - before.linear_velocity) - J).norm(), 1e-12 * J.norm());
    // Angular momentum about the COM: I_world dw = (p - com) x J, I_world = R I_body R^T.
    const Mat3 R = before.pose.orientation.toRotationMatrix();
    const Mat3 I_world = R * b.mass_properties.inertia * R.transpose();
    const Vec3 com = before.pose.apply(b.mass_properties.center_of_mass);
    const Vec3 dL = I_world * (after.angular_velocity - before.angular_velocity);
    const Vec3 expected = (p - com).cross(J);
    EXPECT_LT((dL - expected).norm(), 1e-12 * expected.norm()) << dL.transpose() << " vs " << expected.transpose();
    // The pose is untouched.
    EXPECT_LT((after.pose.position - before.pose.position).norm(), 1e-15);
}

TEST(MujocoBodyFrame, RealBodiesReportTheirPoseAndIgnoreChanges) {
    Scene scene = emptyScene();
    const int floor = addFloor(scene);
    auto backend = makeMujoco(scene);
    BodyState moved;
    moved.pose.position = Vec3(1, 2, 3);
    backend->setBodyState(floor, moved);
    backend->applyImpulse(floor, Vec3(0, 0, 100), Vec3::Zero());
    run(*backend, scene, 5);
    const BodyState s = backend->bodyState(floor);
    EXPECT_EQ(s.pose.position, scene.bodies[floor].pose.position);
    EXPECT_EQ(s.linear_velocity, Vec3::Zero());
}

}  // namespace
}  // namespace vroc::test
