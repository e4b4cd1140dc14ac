// SPDX-License-Identifier: MIT
// Collision events (docs/events.md) for a ball bouncing on the floor.
#include <gtest/gtest.h>

#include <cmath>

#include "test_scenes.h"

namespace vroc::test {
namespace {

TEST(BulletEvents, FirstBounceReportsTheImpulseOfTheRestitutionLaw) {
    const double e = 0.5, m = 2.0, r = 0.1, drop = 1.0, g = 9.81;
    Scene scene = emptyScene(e, 0.5);
    const int floor = addFloor(scene);
    const int ball = addBall(scene, "ball", r, m, Vec3(0.3, -0.2, r + drop));
    auto backend = makeBullet(scene);
    std::vector<CollisionEvent> events;
    double vz_before = 0.0;   // last approach speed seen before the first event
    for (int f = 0; f < 60 && events.empty(); ++f) {
        vz_before = backend->bodyState(ball).linear_velocity.z();
        backend->stepFrame(scene.frame_dt);
        events = backend->takeEvents();
    }
    ASSERT_EQ(events.size(), 1u);
    const CollisionEvent& ev = events[0];
    EXPECT_EQ(ev.body_a, floor);
    EXPECT_EQ(ev.body_b, ball);
    EXPECT_NEAR(ev.time, std::sqrt(2 * drop / g), 2 * scene.frame_dt);
    EXPECT_LT((ev.normal - Vec3::UnitZ()).norm(), 1e-6);   // from the floor (a) to the ball (b)
    EXPECT_NEAR(ev.point.x(), 0.3, 1e-6);
    EXPECT_NEAR(ev.point.y(), -0.2, 1e-6);
    EXPECT_NEAR(ev.point.z(), 0.0, 0.05);
    // Impulse of the restitution law, m (1 + e) v, for the speed at impact (>= last frame's).
    const double v_impact = std::sqrt(2 * g * drop);
    EXPECT_GT(-vz_before, 0.9 * v_impact);
    EXPECT_NEAR(ev.impulse, m * (1 + e) * v_impact, 0.1 * m * (1 + e) * v_impact);
}

TEST(BulletEvents, OneEventPerBounceAndNoneAtRest) {
    Scene scene = emptyScene(0.5, 0.5);
    addFloor(scene);
    addBall(scene, "ball", 0.1, 1.0, Vec3(0, 0, 1.1));
    auto backend = makeBullet(scene);
    std::vector<CollisionEvent> all;
    for (int f = 0; f < 300; ++f) {
        backend->stepFrame(scene.frame_dt);
        for (const auto& ev : backend->takeEvents()) all.push_back(ev);
    }
    // Bounce times of e = 0.5 from 1 m: t1 = sqrt(2h/g), then flights of 2 e^k sqrt(2h/g).
    const double t1 = std::sqrt(2 * 1.0 / 9.81);
    ASSERT_GE(all.size(), 3u);
    EXPECT_NEAR(all[0].time, t1, 2.0 / 60);
    EXPECT_NEAR(all[1].time - all[0].time, 2 * 0.5 * t1, 0.25 * t1);
    for (std::size_t i = 1; i < all.size(); ++i) {
        EXPECT_GT(all[i].time, all[i - 1].time);
        EXPECT_LT(all[i].impulse, all[i - 1].impulse);   // bounces die down
    }
    // The last two seconds (ball at rest) bring no event.
    EXPECT_LT(all.back().time, 3.0);
    backend->stepFrame(scene.frame_dt);
    EXPECT_TRUE(backend->takeEvents().empty());
}

}  // namespace
}  // namespace vroc::test
