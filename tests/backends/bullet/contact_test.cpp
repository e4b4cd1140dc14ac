// SPDX-License-Identifier: MIT
// Resting contact, margins and the material combination rule.
#include <gtest/gtest.h>

#include <cmath>

#include "test_scenes.h"
#include "vroc/core/backend_registry.h"
#include "vroc/core/state_hash.h"

namespace vroc::test {
namespace {

void run(Backend& backend, double dt, int frames) {
    for (int f = 0; f < frames; ++f) backend.stepFrame(dt);
}

TEST(BulletContact, BallRestsOnTheFloorAtItsRadius) {
    Scene scene = emptyScene(0.0, 0.5);
    addFloor(scene);
    const int ball = addBall(scene, "ball", 0.1, 1.0, Vec3(0, 0, 0.15));
    auto backend = makeBullet(scene);
    run(*backend, scene.frame_dt, 120);
    const BodyState s = backend->bodyState(ball);
    SCOPED_TRACE("ball r=0.1 m=1 from z=0.15 on floor top z=0, e=0");
    EXPECT_NEAR(s.pose.position.z(), 0.1, scene.collision_distance);
    EXPECT_LT(s.linear_velocity.norm(), 1e-3);
}

double restingHullGap(bool shrink, double margin) {
    Scene scene = emptyScene(0.0, 0.5);
    addFloor(scene);
    const int cube = addHullCuboid(scene, "cube", Vec3(0.1, 0.1, 0.1), 1.0, Pose{Vec3(0, 0, 0.12), Quat::Identity()});
    auto backend = makeBullet(scene, {{"bullet.shrink_hulls", shrink ? "true" : "false"},
                                      {"bullet.margin", std::to_string(margin)}});
    run(*backend, scene.frame_dt, 120);
    return backend->bodyState(cube).pose.position.z() - 0.1;
}

TEST(BulletContact, ShrunkHullRestsWithItsFaceOnTheFloor) {
    // Face-down cube of half size 0.1 dropped from 2 cm: its centre must settle at 0.1.
    EXPECT_NEAR(restingHullGap(true, 0.04), 0.0, 1e-3);
    EXPECT_NEAR(restingHullGap(true, 0.01), 0.0, 1e-3);
}

TEST(BulletContact, UnshrunkHullFloatsByItsMargin) {
    // Bullet's plain btConvexHullShape grows the hull by its margin: the gap is the margin.
    EXPECT_NEAR(restingHullGap(false, 0.04), 0.04, 1e-3);
    EXPECT_NEAR(restingHullGap(false, 0.01), 0.01, 1e-3);
}

std::uint64_t bounceHash(double e_floor, double e_ball, double mu_floor, double mu_box) {
    Scene scene = emptyScene();
    const int floor_material = addMaterial(scene, "floor", e_floor, mu_floor);
    const int ball_material = addMaterial(scene, "ball", e_ball, mu_box);
    addFloor(scene, floor_material);
    addBall(scene, "ball", 0.1, 1.0, Vec3(0, 0, 1.1), ball_material);
    const int box = addBox(scene, "box", Vec3(0.1, 0.1, 0.1), 1.0, Vec3(1, 0, 0.1), ball_material);
    scene.bodies[box].linear_velocity = Vec3(2, 0, 0);
    auto backend = makeBullet(scene);
    run(*backend, scene.frame_dt, 90);
    return stateHash(*backend);
}

TEST(BulletContact, RestitutionIsTheMinimumAndFrictionTheGeometricMean) {
    // Bullet's default rule (products) would make these runs differ; VROC's rule makes the pair
    // material identical: min(0.2, 0.9) = min(0.9, 0.2) = 0.2, sqrt(0.25 * 1) = sqrt(0.5 * 0.5).
    const std::uint64_t same = bounceHash(0.2, 0.2, 0.5, 0.5);
    EXPECT_EQ(bounceHash(0.2, 0.9, 0.25, 1.0), same);
    EXPECT_EQ(bounceHash(0.9, 0.2, 1.0, 0.25), same);
    EXPECT_NE(bounceHash(0.9, 0.9, 0.5, 0.5), same);   // the comparison can fail
}

TEST(BulletContact, SlidingBoxStopsAfterTheCoulombDistance) {
    // Friction 0.25 and 1.0 combine to 0.5: a box sliding at v stops after v^2 / (2 mu g).
    Scene scene = emptyScene(0.0, 0.5);
    const int floor_material = addMaterial(scene, "floor", 0.0, 0.25);
    const int box_material = addMaterial(scene, "box", 0.0, 1.0);
    addFloor(scene, floor_material);
    const int box = addBox(scene, "box", Vec3(0.1, 0.1, 0.1), 1.0, Vec3(0, 0, 0.1), box_material);
    const double v0 = 3.0;
    scene.bodies[box].linear_velocity = Vec3(v0, 0, 0);
    // 4 sub-steps: this checks the friction mapping, not Bullet's 60 Hz discretisation (2.5 % short).
    auto backend = makeBullet(scene, {{"bullet.substeps", "4"}});
    run(*backend, scene.frame_dt, 120);
    const double expected = v0 * v0 / (2 * 0.5 * 9.81);
    EXPECT_NEAR(backend->bodyState(box).pose.position.x(), expected, 0.02 * expected);
}

TEST(BulletContact, CompoundDumbbellWithOffsetCentreRestsOnBothSpheres) {
    // Two spheres r = 0.1 at x = 0.2 and x = 0.8 of the body frame: COM at x = 0.5, off the
    // origin. Dropped level, it must come to rest level with the body origin at z = r.
    Scene scene = emptyScene(0.0, 0.5);
    addFloor(scene);
    Body b;
    b.name = "dumbbell";
    b.shape = Shape::compound({ShapePart{Shape::sphere(0.1), Pose{Vec3(0.2, 0, 0), Quat::Identity()}},
                               ShapePart{Shape::sphere(0.1), Pose{Vec3(0.8, 0, 0), Quat::Identity()}}});
    b.pose.position = Vec3(-1, 0.5, 0.3);
    const double m = 2.0, ms = 1.0, Is = 0.4 * ms * 0.01;   // each sphere: 1 kg
    b.mass_properties.mass = m;
    b.mass_properties.center_of_mass = Vec3(0.5, 0, 0);
    b.mass_properties.inertia = Vec3(2 * Is, 2 * (Is + ms * 0.09), 2 * (Is + ms * 0.09)).asDiagonal();
    scene.bodies.push_back(b);
    auto backend = makeBullet(scene);
    EXPECT_LT((backend->bodyState(1).pose.position - b.pose.position).norm(), 1e-12);
    run(*backend, scene.frame_dt, 120);
    const BodyState s = backend->bodyState(1);
    SCOPED_TRACE("dumbbell spheres r=0.1 at x=0.2,0.8 (body), origin (-1,0.5,0.3), e=0");
    EXPECT_NEAR(s.pose.position.z(), 0.1, 1e-3);
    EXPECT_NEAR(s.pose.position.x(), -1.0, 1e-3);
    EXPECT_LT(s.pose.orientation.angularDistance(Quat::Identity()), 1e-3);
}

TEST(BulletContact, SameSceneTwiceGivesTheSameStateHash) {
    auto build = [] {
        Scene scene = emptyScene(0.6, 0.4);
        addFloor(scene);
        for (int i = 0; i < 6; ++i)
            addBall(scene, "ball" + std::to_string(i), 0.1, 1.0, Vec3(0.05 * i, 0.03 * i, 0.3 + 0.25 * i));
        addHullCuboid(scene, "hull", Vec3(0.2, 0.1, 0.05), 2.0,
                      Pose{Vec3(0.1, 0, 2.0), Quat(Eigen::AngleAxisd(0.5, Vec3(1, 1, 0).normalized()))},
                      Quat(Eigen::AngleAxisd(0.3, Vec3::UnitZ())), Vec3(0.05, 0, 0));
        return scene;
    };
    auto a = makeBullet(build());
    auto b = makeBullet(build());
    run(*a, 1.0 / 60, 180);
    run(*b, 1.0 / 60, 180);
    EXPECT_EQ(stateHash(*a), stateHash(*b));
    EXPECT_GT(a->statistics().at("collision_events"), 6);   // they did collide
}

}  // namespace
}  // namespace vroc::test

namespace vroc::test {
namespace {

// The declared friction model (registration.cpp: Cone, one row along the slip) against a box sliding
// diagonally: Coulomb's cone keeps the heading and decelerates by mu g along it; two orthogonal rows
// each clamped to mu N (a pyramid) would stop the smaller component first and turn the box toward
// the larger axis.
TEST(BulletFriction, ADiagonalSlideKeepsItsHeadingAsTheDeclaredConeSays) {
    Scene scene = emptyScene(0.0, 0.5);
    addFloor(scene);
    const double heading = 0.5236;   // 30 degrees
    const int box = addBox(scene, "box", Vec3(0.1, 0.1, 0.1), 1.0, Vec3(0, 0, 0.1));
    scene.bodies[static_cast<std::size_t>(box)].linear_velocity = 3.0 * Vec3(std::cos(heading), std::sin(heading), 0);
    auto backend = makeBullet(scene);   // (registers it)
    EXPECT_EQ(BackendRegistry::global().require("bullet").capabilities.friction, FrictionModel::Cone);
    for (int f = 0; f < 12; ++f) backend->stepFrame(scene.frame_dt);   // 0.2 s: still sliding (stops at 3 / (0.5 g) = 0.61 s)
    const Vec3 v = backend->bodyState(box).linear_velocity;
    EXPECT_NEAR(std::atan2(v.y(), v.x()), heading, 0.5 * M_PI / 180);
    EXPECT_NEAR(v.head<2>().norm(), 3.0 - 0.5 * 9.81 * 0.2, 0.05);
}

}  // namespace
}  // namespace vroc::test
