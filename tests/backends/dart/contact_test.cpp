// SPDX-License-Identifier: MIT
// Contacts in DART against closed forms: a box at rest stays put, a ball bounces to e^2 of its drop,
// a slide stops after v^2 / (2 mu g), and the scene's material rule (restitution = min, friction =
// geometric mean) holds between two different materials, not DART's own (product, min).
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "dart_test_scenes.h"
#include "vroc/core/errors.h"

namespace vroc::test {
namespace {

constexpr double kG = 9.81;

// The ball's bottom height at its first apex after the first bounce, from 1 m (frame maxima).
double firstApex(double e_ball, double e_floor, const Overrides& overrides = {}) {
    Scene scene = bareScene();
    const int floor_material = addMaterial(scene, e_floor, 0.5);
    const int ball_material = addMaterial(scene, e_ball, 0.5);
    addFloor(scene, floor_material);
    const int ball = addBall(scene, "ball", 0.1, 1.0, Vec3(0, 0, 1.1), ball_material);
    auto backend = makeDart(scene, overrides);
    bool bounced = false;
    double apex = 0.0;
    for (int f = 0; f < 120; ++f) {
        backend->stepFrame(scene.frame_dt);
        const BodyState s = backend->bodyState(ball);
        if (s.linear_velocity.z() > 0.0) bounced = true;
        if (bounced) apex = std::max(apex, s.pose.position.z() - 0.1);
        if (bounced && s.linear_velocity.z() < 0.0) break;
    }
    return apex;
}

TEST(DartContact, BounceReachesESquaredOfTheDrop) {
    for (double e : {0.5, 0.8}) {
        SCOPED_TRACE(e);
        // Semi-implicit Euler at ~1 ms and frame sampling: within 2 % of e^2 h.
        EXPECT_NEAR(firstApex(e, e), e * e, 0.02 * e * e);
    }
}

TEST(DartContact, RestitutionIsTheSmallerOfTheTwoNotTheirProduct) {
    // min(0.5, 0.8) = 0.5 -> apex 0.25 m; DART's own product 0.4 would give 0.16 m.
    EXPECT_NEAR(firstApex(0.5, 0.8), 0.25, 0.02 * 0.25);
}

// A 0.2 m box (1 kg) sliding at v0 along x on the floor; returns the distance to its stop.
double slideDistance(double mu_box, double mu_floor, double v0, const Overrides& overrides = {}) {
    Scene scene = bareScene();
    const int floor_material = addMaterial(scene, 0.0, mu_floor);
    const int box_material = addMaterial(scene, 0.0, mu_box);
    addFloor(scene, floor_material);
    const int box = addBox(scene, "box", Vec3(0.1, 0.1, 0.1), 1.0, Vec3(0, 0, 0.1), box_material);
    scene.bodies[box].linear_velocity = Vec3(v0, 0, 0);
    auto backend = makeDart(scene, overrides);
    for (int f = 0; f < 90; ++f) backend->stepFrame(scene.frame_dt);
    return backend->bodyState(box).pose.position.x();
}

TEST(DartContact, SlideStopsAfterCoulombsDistance) {
    const double v0 = 2.0, mu = 0.5;
    EXPECT_NEAR(slideDistance(mu, mu, v0), v0 * v0 / (2 * mu * kG), 0.02 * v0 * v0 / (2 * mu * kG));
}

TEST(DartContact, FrictionIsTheGeometricMeanNotTheSmaller) {
    // sqrt(0.2 x 0.8) = 0.4; DART's own min would be 0.2 (twice the distance).
    const double v0 = 2.0, d = v0 * v0 / (2 * 0.4 * kG);
    EXPECT_NEAR(slideDistance(0.2, 0.8, v0), d, 0.02 * d);
}

TEST(DartContact, BoxAtRestStaysAtRest) {
    Scene scene = emptyScene(0.0, 0.6);
    addFloor(scene);
    const int box = addBox(scene, "box", Vec3(0.1, 0.1, 0.1), 1.0, Vec3(0, 0, 0.1005));
    auto backend = makeDart(scene);
    for (int f = 0; f < 120; ++f) backend->stepFrame(scene.frame_dt);
    const BodyState s = backend->bodyState(box);
    EXPECT_NEAR(s.pose.position.z(), 0.1, 2e-3) << "resting on its face (DART corrects depth at <= 1 mm/s)";
    EXPECT_LT(std::hypot(s.pose.position.x(), s.pose.position.y()), 1e-4);
    EXPECT_LT(s.pose.orientation.angularDistance(Quat::Identity()), 1e-3);
    EXPECT_LT(s.linear_velocity.norm(), 1e-2);
}

TEST(DartContact, ALandingIsOneEventWithTheImpulseOfTheBounce) {
    Scene scene = emptyScene(0.5, 0.5);
    addFloor(scene);
    const int ball = addBall(scene, "ball", 0.1, 1.0, Vec3(0, 0, 0.6));
    auto backend = makeDart(scene);
    std::vector<CollisionEvent> events;
    for (int f = 0; f < 25 && events.empty(); ++f) {
        backend->stepFrame(scene.frame_dt);
        for (const CollisionEvent& e : backend->takeEvents()) events.push_back(e);
    }
    ASSERT_EQ(events.size(), 1u);
    const CollisionEvent& e = events[0];
    EXPECT_EQ(e.body_a, 0);
    EXPECT_EQ(e.body_b, ball);
    EXPECT_GT(e.normal.z(), 0.99) << "from the floor (a) to the ball (b)";
    // (1 + e) m v at v = sqrt(2 g 0.5): the impact impulse, within the step's gravity and ERP.
    EXPECT_NEAR(e.impulse, 1.5 * std::sqrt(2 * kG * 0.5), 0.05 * 1.5 * std::sqrt(2 * kG * 0.5));
    EXPECT_NEAR(e.time, std::sqrt(2 * 0.5 / kG), 2.0 / 1000);
}

// FCL's own sphere misses a triangle-mesh hull: a 0.1 m ball dropped on a static 0.5 m-tall hull
// block must rest on its top face (centre at 0.5 + 0.1 m), not fall through to the floor.
TEST(DartContact, ABallRestsOnAStaticHullInsteadOfFallingThrough) {
    Scene scene = bareScene();
    const int m = addMaterial(scene, 0.0, 0.5);
    addFloor(scene, m);
    addBody(scene, "block", Shape::convexHull(ConvexPolyhedron::box(Vec3(0.5, 0.5, 0.25))), at(Vec3(0, 0, 0.25)), m,
            true);
    const int ball = addBall(scene, "ball", 0.1, 1.0, Vec3(0, 0, 1.0), m);
    auto backend = makeDart(scene);
    for (int f = 0; f < 60; ++f) backend->stepFrame(scene.frame_dt);
    EXPECT_NEAR(backend->bodyState(ball).pose.position.z(), 0.6, 2e-3);
    EXPECT_EQ(backend->statistics().at("dart.mesh_collision_for_hulls"), 1.0);
}

}  // namespace
}  // namespace vroc::test
