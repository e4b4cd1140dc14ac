// SPDX-License-Identifier: MIT
// Tracked bodies (role "tracked"): infinite mass, prescribed motion, their velocity in the impulse.
// Answers are closed forms: a body of infinite mass moving at u strikes a free body at rest along
// the normal n, frictionless, restitution e: the free body leaves with (1 + e) (u . n) n.
#include <gtest/gtest.h>

#include <cmath>

#include "native_test_scenes.h"

namespace vroc::native::test {
namespace {

/// No gravity: a ball of radius 0.1 at rest at the origin, a plate (tracked box, 2 cm thick)
/// approaching along +x at `speed` from x = -0.5.
struct PlateStrike {
    Scene scene = bareScene(1e-3, Vec3::Zero());
    int ball = -1, plate = -1;
    PlateStrike(double speed, double restitution) {
        const int m = addMaterial(scene, restitution, 0.0);
        ball = addBody(scene, "ball", Shape::sphere(0.1), at(Vec3::Zero()), m, false, 0.3);
        plate = addTracked(scene, "plate", Shape::box(Vec3(0.01, 0.2, 0.2)), at(Vec3(-0.5, 0, 0)), m,
                           Vec3(speed, 0, 0));
    }
};

TEST(NativeTracked, PlateStrikesBallAtRestWhichLeavesAtOnePlusETimesPlateSpeed) {
    for (double e : {0.0, 0.5, 1.0}) {
        PlateStrike s(2.0, e);
        auto backend = makeBackend(s.scene);
        std::vector<CollisionEvent> events;
        for (int f = 1; f <= 30; ++f) {
            backend->stepFrame(1.0 / 60.0);
            for (const CollisionEvent& ev : backend->takeEvents()) events.push_back(ev);
            // The plate moves exactly as prescribed, whatever it strikes.
            const BodyState plate = backend->bodyState(s.plate);
            EXPECT_NEAR(plate.pose.position.x(), -0.5 + 2.0 * backend->time(), 1e-12);
            EXPECT_DOUBLE_EQ(plate.linear_velocity.x(), 2.0);
            EXPECT_TRUE(plate.pose.orientation.isApprox(Quat::Identity(), 1e-15));
        }
        ASSERT_EQ(events.size(), 1u) << "e = " << e;
        // Contact when the plate's face (x = -0.49 + 2 t) meets the ball (x = -0.1), within the
        // collision distance.
        EXPECT_NEAR(events[0].time, 0.39 / 2.0, 1e-3 / 2.0 + 1e-9);
        EXPECT_NEAR(events[0].impulse, 0.3 * (1.0 + e) * 2.0, 1e-9) << "e = " << e;
        const BodyState ball = backend->bodyState(s.ball);
        EXPECT_NEAR(ball.linear_velocity.x(), (1.0 + e) * 2.0, 1e-9) << "e = " << e;
        EXPECT_NEAR(ball.linear_velocity.tail<2>().norm(), 0.0, 1e-12);
        EXPECT_NEAR(ball.angular_velocity.norm(), 0.0, 1e-12);
        // The ball is never inside the plate: at e = 0 they travel together, touching.
        const double gap = (ball.pose.position.x() - 0.1) - (backend->bodyState(s.plate).pose.position.x() + 0.01);
        EXPECT_GT(gap, -1e-3) << "e = " << e;
    }
}

TEST(NativeTracked, SpinningPaddleGivesTheBallItsContactPointSpeed) {
    // A paddle (a long box along its x axis) spins about the world z axis through its centre at
    // omega; a ball at rest at radius 0.3 is struck by the paddle's face. At the contact point
    // p, the paddle's surface moves at omega x p, which is along the face normal: the ball leaves
    // with (1 + e) |omega| (p . axis) along that normal (frictionless, infinite mass).
    // On fixed ticks too: the ball is alone with the paddle (a tracked body), so its impact is
    // deferred to its touching time and met there, with the paddle where it is then (met at the
    // tick's start instead, the ball left 3.6 % off).
    for (TouchingRegime regime : {TouchingRegime::Protected, TouchingRegime::Fixed}) {
        SCOPED_TRACE(regime == TouchingRegime::Fixed ? "fixed ticks" : "default regime");
        NativeSettings ns;
        ns.touching = regime;
        const double omega = 6.0, e = 0.5;
        Scene scene = bareScene(1e-3, Vec3::Zero());
        const int m = addMaterial(scene, e, 0.0);
        const int ball = addBody(scene, "ball", Shape::sphere(0.05), at(Vec3(0.0, 0.3, 0)), m, false, 0.2);
        const Quat start(Eigen::AngleAxisd(-0.6, Vec3::UnitZ()));
        const int paddle = addTracked(scene, "paddle", Shape::box(Vec3(0.5, 0.02, 0.1)), at(Vec3::Zero(), start), m,
                                      Vec3::Zero(), Vec3(0, 0, omega));
        auto backend = makeBackend(scene, ns);
        std::vector<CollisionEvent> events;
        for (int f = 0; f < 60 && events.empty(); ++f) {   // until the frame of the strike
            backend->stepFrame(1.0 / 120.0);
            for (const CollisionEvent& ev : backend->takeEvents()) events.push_back(ev);
            const BodyState p = backend->bodyState(paddle);
            const Quat expected = Quat(Eigen::AngleAxisd(omega * backend->time(), Vec3::UnitZ())) * start;
            EXPECT_LT(p.pose.orientation.angularDistance(expected), 1e-12);
            EXPECT_NEAR(p.pose.position.norm(), 0.0, 1e-15);
        }
        ASSERT_EQ(events.size(), 1u);
        const CollisionEvent& hit = events[0];
        // The paddle's pose at the contact time, in closed form.
        const Quat q = Quat(Eigen::AngleAxisd(omega * hit.time, Vec3::UnitZ())) * start;
        const Vec3 axis = q * Vec3::UnitX();
        const Vec3 face_normal = q * Vec3::UnitY();   // the face that sweeps towards the ball
        const double r = hit.point.dot(axis);
        const Vec3 expected_v = (1.0 + e) * omega * r * face_normal;
        const BodyState b = backend->bodyState(ball);
        EXPECT_NEAR((b.linear_velocity - expected_v).norm(), 0.0, 2e-3 * expected_v.norm())
            << "got " << b.linear_velocity.transpose() << ", expected " << expected_v.transpose();
        EXPECT_GT(r, 0.25);
        EXPECT_LT(r, 0.35);
    }
}

TEST(NativeTracked, SetBodyStateIsATrackerSampleTheBodyMovesOnFrom) {
    PlateStrike s(0.0, 0.5);
    auto backend = makeBackend(s.scene);
    backend->stepFrame(0.1);
    BodyState sample;
    sample.pose = at(Vec3(-0.8, 0.05, 0.0), Quat(Eigen::AngleAxisd(0.2, Vec3::UnitY())));
    sample.linear_velocity = Vec3(1.5, 0, 0);
    sample.angular_velocity = Vec3::Zero();
    backend->setBodyState(s.plate, sample);
    const double t0 = backend->time();
    for (int f = 0; f < 10; ++f) {
        backend->stepFrame(0.01);
        const BodyState p = backend->bodyState(s.plate);
        EXPECT_NEAR((p.pose.position - (sample.pose.position + sample.linear_velocity * (backend->time() - t0))).norm(),
                    0.0, 1e-12);
        EXPECT_LT(p.pose.orientation.angularDistance(sample.pose.orientation), 1e-15);
    }
    // An impulse never moves a tracked body.
    backend->applyImpulse(s.plate, Vec3(100, 0, 0), sample.pose.position);
    EXPECT_DOUBLE_EQ(backend->bodyState(s.plate).linear_velocity.x(), 1.5);
    // A non-finite sample is refused and counted; the body keeps its motion.
    BodyState bad = sample;
    bad.linear_velocity.x() = std::nan("");
    backend->setBodyState(s.plate, bad);
    EXPECT_EQ(backend->warnings().at("nonfinite_state"), 1u);
    EXPECT_DOUBLE_EQ(backend->bodyState(s.plate).linear_velocity.x(), 1.5);
}

TEST(NativeTracked, PlatformLiftsARestingBoxAtItsOwnSpeed) {
    // A box resting on a tracked platform that rises at 0.5 m/s under gravity: the box rides on
    // it (velocity 0.5 m/s up, touching, never inside), a contact held by the contact phase.
    Scene scene = bareScene();
    const int m = addMaterial(scene, 0.2, 0.6);
    const int platform = addTracked(scene, "platform", Shape::box(Vec3(0.5, 0.5, 0.05)), at(Vec3(0, 0, -0.05)), m,
                                    Vec3(0, 0, 0.5));
    const int box = addBody(scene, "box", Shape::box(Vec3(0.1, 0.1, 0.1)), at(Vec3(0, 0, 0.1005)), m, false, 2.0);
    auto backend = makeBackend(scene);
    for (int f = 0; f < 120; ++f) {
        backend->stepFrame(1.0 / 60.0);
        const double top = backend->bodyState(platform).pose.position.z() + 0.05;
        const double bottom = backend->bodyState(box).pose.position.z() - 0.1;
        EXPECT_GT(bottom - top, -1e-3) << "frame " << f;
        if (f > 30) {
            EXPECT_LT(bottom - top, 2e-3) << "frame " << f;
            EXPECT_NEAR(backend->bodyState(box).linear_velocity.z(), 0.5, 0.05) << "frame " << f;
        }
    }
    EXPECT_EQ(backend->warnings().count("penetration_recovered"), 0u);
}

TEST(NativeTracked, TrackedBodyPassesThroughRealBodiesWithoutResponse) {
    // Two bodies of infinite mass have no response: the tracked plate moves through the static
    // floor untouched and no event is reported for the pair.
    Scene scene = bareScene();
    const int m = addMaterial(scene, 0.5, 0.5);
    addFloor(scene, m, 20.0);
    const int plate = addTracked(scene, "plate", Shape::box(Vec3(0.2, 0.2, 0.01)), at(Vec3(0, 0, 0.5)), m,
                                 Vec3(0, 0, -1.0));
    auto backend = makeBackend(scene);
    for (int f = 0; f < 60; ++f) {
        backend->stepFrame(1.0 / 60.0);
        EXPECT_TRUE(backend->takeEvents().empty());
    }
    EXPECT_NEAR(backend->bodyState(plate).pose.position.z(), 0.5 - 1.0, 1e-12);
    EXPECT_TRUE(backend->warnings().empty());
}

}  // namespace
}  // namespace vroc::native::test

namespace vroc::native::test {
namespace {

TEST(NativeTracked, SleepingBoxOnAPlatformWakesWhenThePlatformMoves) {
    Scene scene = bareScene();
    const int m = addMaterial(scene, 0.2, 0.6);
    const int platform = addTracked(scene, "platform", Shape::box(Vec3(0.5, 0.5, 0.05)), at(Vec3(0, 0, -0.05)), m,
                                    Vec3::Zero());
    const int box = addBody(scene, "box", Shape::box(Vec3(0.1, 0.1, 0.1)), at(Vec3(0, 0, 0.1005)), m, false, 2.0);
    NativeSettings settings;
    settings.sleeping = true;
    auto backend = makeBackend(scene, settings);
    for (int f = 0; f < 120; ++f) backend->stepFrame(1.0 / 60.0);
    ASSERT_GE(backend->statistics().at("native.islands_slept"), 1.0) << "the box should be asleep on the still platform";
    BodyState lift = backend->bodyState(platform);
    lift.linear_velocity = Vec3(0, 0, 0.5);
    backend->setBodyState(platform, lift);
    for (int f = 0; f < 60; ++f) {
        backend->stepFrame(1.0 / 60.0);
        const double gap = (backend->bodyState(box).pose.position.z() - 0.1) -
                           (backend->bodyState(platform).pose.position.z() + 0.05);
        EXPECT_GT(gap, -1e-3) << "frame " << f;
    }
    EXPECT_NEAR(backend->bodyState(box).linear_velocity.z(), 0.5, 0.05);
}

TEST(NativeTracked, BoxOnASlowlySinkingPlatformNeverSleepsInTheAir) {
    // The platform sinks at 5 mm/s, below the sleep speed: a box resting on it is still by the
    // speed test, but it touches a moving real object, so it stays awake and follows it down.
    Scene scene = bareScene();
    const int m = addMaterial(scene, 0.2, 0.6);
    const int platform = addTracked(scene, "platform", Shape::box(Vec3(0.5, 0.5, 0.05)), at(Vec3(0, 0, -0.05)), m,
                                    Vec3(0, 0, -0.005));
    const int box = addBody(scene, "box", Shape::box(Vec3(0.1, 0.1, 0.1)), at(Vec3(0, 0, 0.1005)), m, false, 2.0);
    NativeSettings settings;
    settings.sleeping = true;
    auto backend = makeBackend(scene, settings);
    for (int f = 0; f < 240; ++f) backend->stepFrame(1.0 / 60.0);
    const double gap = (backend->bodyState(box).pose.position.z() - 0.1) -
                       (backend->bodyState(platform).pose.position.z() + 0.05);
    EXPECT_LT(gap, 2e-3);
    EXPECT_GT(gap, -1e-3);
}

}  // namespace
}  // namespace vroc::native::test
