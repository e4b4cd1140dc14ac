// SPDX-License-Identifier: MIT
// The DART backend's side of the contract: bad input is an InputError, nothing non-finite leaves
// the backend, the same scene gives the same bits, a tracked platform carries a box.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "dart_test_scenes.h"
#include "vroc/core/errors.h"
#include "vroc/core/state_hash.h"

namespace vroc::test {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(DartContract, BadInputIsRefused) {
    Scene scene = emptyScene();
    addFloor(scene);
    const int ball = addBall(scene, "ball", 0.1, 1.0, Vec3(0, 0, 1));
    {
        Scene bad = scene;
        bad.bodies[ball].material = 7;
        EXPECT_THROW(makeDart(bad), InputError);
    }
    {
        Scene bad = scene;
        bad.bodies[ball].shape = Shape::sphere(0.0);
        EXPECT_THROW(makeDart(bad), InputError);
    }
    {
        Scene bad = scene;
        bad.bodies[ball].mass_properties.mass = 0.0;
        EXPECT_THROW(makeDart(bad), InputError);
    }
    {
        Scene bad = scene;
        ConvexPolyhedron flat;
        flat.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
        flat.faces = {{0, 1, 2}};
        bad.bodies[ball].shape = Shape::convexHull(flat);
        EXPECT_THROW(makeDart(bad), InputError);
    }
    EXPECT_THROW(makeDart(scene, {{"dart.primitive_shapes", "cones"}}), InputError);
    EXPECT_THROW(makeDart(scene, {{"dart.timestep", "-1"}}), InputError);
    auto backend = makeDart(scene);
    EXPECT_THROW(backend->stepFrame(0.0), InputError);
    EXPECT_THROW(backend->stepFrame(kNaN), InputError);
    EXPECT_THROW(backend->bodyState(2), InputError);
    EXPECT_THROW(backend->setBodyState(-1, BodyState{}), InputError);
    EXPECT_THROW(backend->applyImpulse(5, Vec3::UnitX(), Vec3::Zero()), InputError);
}

TEST(DartContract, NonFiniteInputIsCountedAndRefused) {
    Scene scene = emptyScene();
    const int ball = addBall(scene, "ball", 0.1, 1.0, Vec3(0, 0, 1));
    auto backend = makeDart(scene);
    const BodyState before = backend->bodyState(ball);
    BodyState bad = before;
    bad.linear_velocity.x() = kNaN;
    backend->setBodyState(ball, bad);
    backend->applyImpulse(ball, Vec3(kNaN, 0, 0), Vec3::Zero());
    EXPECT_EQ(backend->warnings().at("nonfinite_state"), 2u);
    backend->stepFrame(scene.frame_dt);
    const BodyState s = backend->bodyState(ball);
    EXPECT_TRUE(s.pose.position.allFinite() && s.linear_velocity.allFinite() && s.angular_velocity.allFinite());
    // A huge but finite state: whatever DART makes of it, nothing non-finite comes out.
    BodyState huge = before;
    huge.linear_velocity = Vec3(1e300, -1e300, 1e300);
    huge.angular_velocity = Vec3(1e300, 1e300, 0);
    backend->setBodyState(ball, huge);
    for (int f = 0; f < 3; ++f) backend->stepFrame(scene.frame_dt);
    const BodyState h = backend->bodyState(ball);
    EXPECT_TRUE(h.pose.position.allFinite() && h.pose.orientation.coeffs().allFinite() &&
                h.linear_velocity.allFinite() && h.angular_velocity.allFinite());
}

// Boxes, balls and hulls dropped in a heap: two runs give the same state hash.
Scene heap() {
    Scene scene = emptyScene(0.3, 0.6);
    addFloor(scene);
    for (int i = 0; i < 9; ++i) {
        const Vec3 p(0.05 * (i % 3), 0.04 * (i / 3), 0.15 + 0.22 * i);
        const Quat q(Eigen::AngleAxisd(0.3 * i, Vec3(1, 1, 0).normalized()));
        if (i % 3 == 0) addBall(scene, "ball" + std::to_string(i), 0.08, 1.0, p);
        if (i % 3 == 1) addBox(scene, "box" + std::to_string(i), Vec3(0.1, 0.07, 0.05), 1.0, p);
        if (i % 3 == 2) addHullCuboid(scene, "hull" + std::to_string(i), Vec3(0.06, 0.08, 0.1), 1.0, at(p, q));
    }
    return scene;
}

TEST(DartContract, SameSceneGivesTheSameStateHash) {
    const Scene scene = heap();
    std::uint64_t hashes[2] = {0, 0};
    for (std::uint64_t& hash : hashes) {
        auto backend = makeDart(scene);
        for (int f = 0; f < 60; ++f) backend->stepFrame(scene.frame_dt);
        hash = stateHash(*backend);
        EXPECT_GT(backend->statistics().at("collision_events"), 5.0) << "the heap did collide";
    }
    EXPECT_EQ(hashes[0], hashes[1]);
}

TEST(DartContract, ATrackedPlatformCarriesABox) {
    const double speed = 0.5;
    const std::vector<LiftSample> lift =
        trackedLift([](const Scene& s, const Overrides& o) { return makeDart(s, o); }, speed, 1.0 / 60.0, 60);
    ASSERT_FALSE(lift.empty());
    EXPECT_NEAR(lift.back().box_vz, speed, 0.02);
    EXPECT_LT(std::abs(lift.back().gap), 3e-3);
}

}  // namespace
}  // namespace vroc::test
