// SPDX-License-Identifier: MIT
// Free motion in ODE against closed forms: free fall is semi-implicit Euler exactly, and the body
// frame (not ODE's centre-of-mass frame) is what bodyState reports.
#include <gtest/gtest.h>

#include <cmath>

#include "ode_test_scenes.h"

namespace vroc::test {
namespace {

TEST(OdeMotion, FreeFallIsSemiImplicitEuler) {
    Scene scene = emptyScene();
    const Vec3 x0(0.5, -1, 10), v0(1, 0, 2);
    const int ball = addBall(scene, "ball", 0.1, 2.0, x0);
    scene.bodies[ball].linear_velocity = v0;
    auto backend = makeOde(scene);
    const double h = scene.frame_dt;
    const int n = 120;
    for (int f = 0; f < n; ++f) backend->stepFrame(h);
    // v_k = v_{k-1} + g h, x_k = x_{k-1} + h v_k  =>  x_n = x0 + n h v0 + g h^2 n (n + 1) / 2.
    const Vec3 expected = x0 + n * h * v0 + scene.gravity * (h * h * n * (n + 1) / 2.0);
    const BodyState s = backend->bodyState(ball);
    EXPECT_LT((s.pose.position - expected).norm(), 1e-12 * expected.norm());
    EXPECT_LT((s.linear_velocity - (v0 + n * h * scene.gravity)).norm(), 1e-12 * v0.norm() * 10);
    EXPECT_NEAR(backend->time(), n * h, 1e-12);
}

TEST(OdeMotion, SubstepsDivideTheFrame) {
    Scene scene = emptyScene();
    const int ball = addBall(scene, "ball", 0.1, 1.0, Vec3(0, 0, 5));
    auto backend = makeOde(scene, {{"ode.substeps", "4"}});
    const double h = scene.frame_dt / 4;
    const int n = 4 * 30;
    for (int f = 0; f < 30; ++f) backend->stepFrame(scene.frame_dt);
    const double z = 5 + scene.gravity.z() * h * h * n * (n + 1) / 2.0;
    EXPECT_NEAR(backend->bodyState(ball).pose.position.z(), z, 1e-12 * 5);
    EXPECT_EQ(backend->statistics().at("internal_steps"), 120.0);
    EXPECT_EQ(backend->statistics().at("frames"), 30.0);
}

// A hull whose centre of mass is off the body origin and whose inertia is not diagonal in body
// axes: bodyState reports the scene's body frame, and a torque-free spin keeps the COM in place.
TEST(OdeMotion, BodyFrameIsTheScenesNotTheCentreOfMass) {
    Scene scene = emptyScene();
    scene.gravity = Vec3::Zero();
    const Quat rot(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
    const Vec3 centre(0.3, -0.2, 0.1);
    const Pose pose{Vec3(1, 2, 3), Quat(Eigen::AngleAxisd(0.4, Vec3(0, 1, 1).normalized()))};
    const int body = addHullCuboid(scene, "hull", Vec3(0.2, 0.1, 0.05), 3.0, pose, rot, centre);
    // Spin about a principal axis (the cuboid's local x, in world): steady, torque-free.
    const Vec3 axis_world = pose.orientation * (rot * Vec3::UnitX());
    scene.bodies[body].angular_velocity = 2.0 * axis_world;
    auto backend = makeOde(scene);

    const BodyState s0 = backend->bodyState(body);
    EXPECT_LT((s0.pose.position - pose.position).norm(), 1e-12);
    EXPECT_LT(s0.pose.orientation.angularDistance(pose.orientation), 1e-12);

    const Vec3 com0 = pose.apply(centre);
    for (int f = 0; f < 120; ++f) backend->stepFrame(scene.frame_dt);
    const BodyState s = backend->bodyState(body);
    EXPECT_LT((s.pose.apply(centre) - com0).norm(), 1e-12) << "the COM must not move";
    EXPECT_LT((s.angular_velocity - 2.0 * axis_world).norm(), 1e-9) << "principal-axis spin is steady";
    EXPECT_GT(s.pose.orientation.angularDistance(pose.orientation), 1.0) << "it did turn";
}

}  // namespace
}  // namespace vroc::test
