// SPDX-License-Identifier: MIT
// Collision events, determinism and numerical trouble.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "test_scenes.h"
#include "vroc/core/errors.h"
#include "vroc/core/state_hash.h"

namespace vroc::test {
namespace {

TEST(MujocoEvents, FirstBounceOfABall) {
    // 2 kg ball, e = 0.5, bottom 1 m above the floor: one event per bounce, floor (a = 0) to ball
    // (b = 1), normal +z, point under the ball. MuJoCo's soft contact spreads the collision over
    // several steps; the event carries the first step's share of m (1 + e) v.
    Scene scene = emptyScene(0.5, 0.5);
    addFloor(scene);
    const int ball = addBall(scene, "ball", 0.1, 2.0, Vec3(0.3, -0.2, 1.1));
    auto backend = makeMujoco(scene);
    std::vector<CollisionEvent> events;
    for (int f = 0; f < 90; ++f) {
        backend->stepFrame(scene.frame_dt);
        for (const CollisionEvent& e : backend->takeEvents()) events.push_back(e);
    }
    ASSERT_GE(events.size(), 1u);
    const CollisionEvent& e = events.front();
    EXPECT_EQ(e.body_a, 0);
    EXPECT_EQ(e.body_b, ball);
    EXPECT_LT((e.normal - Vec3::UnitZ()).norm(), 1e-9) << e.normal.transpose();
    EXPECT_NEAR(e.point.x(), 0.3, 1e-6);
    EXPECT_NEAR(e.point.y(), -0.2, 1e-6);
    EXPECT_NEAR(e.point.z(), 0.0, 0.01);
    const double v = std::sqrt(2 * 9.81 * 1.0), full = 2.0 * 1.5 * v;
    EXPECT_NEAR(e.time, std::sqrt(2.0 / 9.81), 2 * scene.frame_dt / 9 + 1e-9);
    EXPECT_GT(e.impulse, 0.0);
    EXPECT_LT(e.impulse, full);
    std::printf("first bounce: t = %.4f s (free fall %.4f s), impulse %.4f N s = %.1f %% of m(1+e)v = %.4f N s; "
                "%zu events in 1.5 s\n",
                e.time, std::sqrt(2.0 / 9.81), e.impulse, 100 * e.impulse / full, full, events.size());
    // One event per bounce: the second event comes after the ball left the floor.
    if (events.size() > 1) {
        EXPECT_GT(events[1].time - events[0].time, 0.3);
    }
}

TEST(MujocoDeterminism, SameSceneSameBits) {
    auto once = [] {
        Scene scene = emptyScene(0.5, 0.6);
        addFloor(scene);
        for (int i = 0; i < 4; ++i) {
            const int b = addBox(scene, "box" + std::to_string(i), Vec3(0.1, 0.08, 0.06), 1.0 + i,
                                 Vec3(0.05 * i, 0.03 * i, 0.2 + 0.25 * i));
            scene.bodies[b].angular_velocity = Vec3(0.5 * i, -0.3, 0.2);
            Pose pose;
            pose.position = Vec3(0.5, 0.02 * i, 0.3 + 0.3 * i);
            pose.orientation = Quat(Eigen::AngleAxisd(0.3 * i, Vec3(1, 1, 0).normalized()));
            addHullCuboid(scene, "hull" + std::to_string(i), Vec3(0.07, 0.07, 0.05), 0.5, pose);
            addBall(scene, "ball" + std::to_string(i), 0.05, 0.3, Vec3(-0.4, 0.1 * i, 0.2 + 0.2 * i));
        }
        auto backend = makeMujoco(scene);
        run(*backend, scene, 120);
        return stateHash(*backend);
    };
    const std::uint64_t a = once(), b = once();
    EXPECT_EQ(a, b);
    std::printf("state hash after 2 s: %s\n", hashToHex(a).c_str());
}

TEST(MujocoTrouble, NonFiniteInputIsRefusedAndCounted) {
    Scene scene = emptyScene();
    addFloor(scene);
    const int ball = addBall(scene, "ball", 0.1, 1.0, Vec3(0, 0, 1));
    auto backend = makeMujoco(scene);
    run(*backend, scene, 3);
    const BodyState before = backend->bodyState(ball);
    BodyState bad = before;
    bad.linear_velocity.x() = std::numeric_limits<double>::quiet_NaN();
    backend->setBodyState(ball, bad);
    BodyState zero_q = before;
    zero_q.pose.orientation.coeffs().setZero();
    EXPECT_THROW(backend->setBodyState(ball, zero_q), InputError);   // finite: the caller's mistake
    backend->applyImpulse(ball, Vec3(0, 0, std::numeric_limits<double>::infinity()), Vec3::Zero());
    backend->applyImpulse(ball, Vec3::UnitZ(), Vec3(std::numeric_limits<double>::quiet_NaN(), 0, 0));
    EXPECT_EQ(backend->warnings().at("nonfinite_state"), 3u);
    const BodyState after = backend->bodyState(ball);
    EXPECT_EQ(after.pose.position, before.pose.position);
    EXPECT_EQ(after.linear_velocity, before.linear_velocity);
}

TEST(MujocoTrouble, HugeStateIsCountedAndRecovered) {
    // Finite but beyond MuJoCo's 1e10 bound: MuJoCo flags the velocity and resets its whole state;
    // the backend counts it and puts the ball back to its state after the last good step, from
    // which it falls on. Another ball, untouched, keeps its own motion.
    Scene scene = emptyScene();
    addFloor(scene);
    const int ball = addBall(scene, "ball", 0.1, 1.0, Vec3(0, 0, 1));
    const int other = addBall(scene, "other", 0.1, 1.0, Vec3(2, 0, 2));
    auto backend = makeMujoco(scene);
    run(*backend, scene, 5);
    const BodyState good = backend->bodyState(ball);
    BodyState wild = good;
    wild.linear_velocity.x() = 1e11;
    backend->setBodyState(ball, wild);
    const double other_z = backend->bodyState(other).pose.position.z();
    backend->stepFrame(scene.frame_dt);
    const WarningCounts w = backend->warnings();
    EXPECT_EQ(w.at("nonfinite_state"), 1u);
    EXPECT_EQ(w.at("mujoco.bad_qvel"), 1u);
    const BodyState s = backend->bodyState(ball);
    ASSERT_TRUE(s.pose.position.allFinite() && s.linear_velocity.allFinite());
    EXPECT_LT(std::abs(s.linear_velocity.x()), 1e-9);
    EXPECT_LT(s.pose.position.z(), good.pose.position.z());   // the frame was simulated from the good state
    EXPECT_LT(backend->bodyState(other).pose.position.z(), other_z);
    run(*backend, scene, 10);
    EXPECT_LT(backend->bodyState(ball).pose.position.z(), s.pose.position.z() - 0.05);
    std::printf("warnings after recovery:");
    for (const auto& [name, count] : backend->warnings()) std::printf(" %s=%llu", name.c_str(), static_cast<unsigned long long>(count));
    std::printf("\n");
}

}  // namespace
}  // namespace vroc::test
