// SPDX-License-Identifier: MIT
// Free motion in DART against closed forms: World::step is semi-implicit Euler (velocity, then
// position), a frame is cut into equal steps no longer than dart.timestep, and the body frame (not
// DART's centre-of-mass frame) is what bodyState reports.
#include <cmath>

#include <gtest/gtest.h>

#include "dart_test_scenes.h"

namespace vroc::test {
namespace {

// v_k = v_{k-1} + g h, x_k = x_{k-1} + h v_k  =>  x_n = x0 + n h v0 + g h^2 n (n + 1) / 2.
Vec3 eulerPosition(const Vec3& x0, const Vec3& v0, const Vec3& g, double h, int n) {
    return x0 + n * h * v0 + g * (h * h * n * (n + 1) / 2.0);
}

TEST(DartMotion, FreeFallIsSemiImplicitEulerAtDartsOwnStep) {
    Scene scene = emptyScene();
    const Vec3 x0(0.5, -1, 10), v0(1, 0, 2);
    const int ball = addBall(scene, "ball", 0.1, 2.0, x0);
    scene.bodies[ball].linear_velocity = v0;
    auto backend = makeDart(scene);
    const int frames = 30;
    for (int f = 0; f < frames; ++f) backend->stepFrame(scene.frame_dt);
    // 1/60 s at steps of at most 1 ms: 17 steps a frame.
    const int n = 17 * frames;
    const double h = scene.frame_dt / 17;
    const BodyState s = backend->bodyState(ball);
    const Vec3 expected = eulerPosition(x0, v0, scene.gravity, h, n);
    EXPECT_LT((s.pose.position - expected).norm(), 1e-11 * expected.norm());
    EXPECT_LT((s.linear_velocity - (v0 + n * h * scene.gravity)).norm(), 1e-11);
    EXPECT_EQ(backend->statistics().at("internal_steps"), static_cast<double>(n));
    EXPECT_NEAR(backend->time(), frames * scene.frame_dt, 1e-12);
    // First order: within g h t / 2 of the exact parabola.
    const double t = frames * scene.frame_dt;
    const Vec3 exact = x0 + v0 * t + 0.5 * scene.gravity * t * t;
    EXPECT_NEAR((s.pose.position - exact).norm(), 9.81 * h * t / 2, 1e-9);
}

TEST(DartMotion, SubstepsDivideTheFrame) {
    Scene scene = emptyScene();
    const int ball = addBall(scene, "ball", 0.1, 1.0, Vec3(0, 0, 5));
    auto backend = makeDart(scene, {{"dart.substeps", "4"}});
    const double h = scene.frame_dt / 4;
    for (int f = 0; f < 30; ++f) backend->stepFrame(scene.frame_dt);
    const Vec3 expected = eulerPosition(Vec3(0, 0, 5), Vec3::Zero(), scene.gravity, h, 120);
    EXPECT_NEAR(backend->bodyState(ball).pose.position.z(), expected.z(), 1e-12 * 5);
    EXPECT_EQ(backend->statistics().at("internal_steps"), 120.0);
    EXPECT_EQ(backend->statistics().at("frames"), 30.0);
}

// A hull whose centre of mass is off the body origin and whose inertia is not diagonal in body
// axes: bodyState reports the scene's body frame, and a torque-free spin keeps the COM in place.
TEST(DartMotion, BodyFrameIsTheScenesNotTheCentreOfMass) {
    Scene scene = emptyScene();
    scene.gravity = Vec3::Zero();
    const Quat rot(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
    const Vec3 centre(0.3, -0.2, 0.1);
    const Pose pose{Vec3(1, 2, 3), Quat(Eigen::AngleAxisd(0.4, Vec3(0, 1, 1).normalized()))};
    const int body = addHullCuboid(scene, "hull", Vec3(0.2, 0.1, 0.05), 3.0, pose, rot, centre);
    const Vec3 axis_world = pose.orientation * (rot * Vec3::UnitX());  // a principal axis: steady spin
    scene.bodies[body].angular_velocity = 2.0 * axis_world;
    auto backend = makeDart(scene);

    const BodyState s0 = backend->bodyState(body);
    EXPECT_LT((s0.pose.position - pose.position).norm(), 1e-12);
    EXPECT_LT(s0.pose.orientation.angularDistance(pose.orientation), 1e-12);

    const Vec3 com0 = pose.apply(centre);
    for (int f = 0; f < 60; ++f) backend->stepFrame(scene.frame_dt);
    const BodyState s = backend->bodyState(body);
    EXPECT_LT((s.pose.apply(centre) - com0).norm(), 1e-12) << "the COM must not move";
    EXPECT_LT((s.angular_velocity - 2.0 * axis_world).norm(), 1e-9) << "principal-axis spin is steady";
    EXPECT_GT(s.pose.orientation.angularDistance(pose.orientation), 1.0) << "it did turn";
}

}  // namespace
}  // namespace vroc::test
