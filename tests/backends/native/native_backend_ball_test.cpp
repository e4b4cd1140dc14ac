// SPDX-License-Identifier: MIT
// Ball drop (comparison-methodology §3.2): apexes h_n = e^(2n) h measured from the floor top (the
// ball's lowest point above z = 0, as issue 4 states), exact parabolic flight between bounces.
// Impacts are resolved at touching (scheduling/contact_time_refinement.h), not at the collision
// window, so no offset of the contact level enters the apexes.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "native_test_scenes.h"

namespace vroc::native::test {
namespace {

struct Bounce {
    double apex = -1.0;         // [m] bottom height at the apex, from the energy of the flight
    int frames_in_flight = 0;
    double worst_flight_error = 0.0;   // [m] vs the parabola through the first ascending frame
};

// Drops a ball of radius r from bottom height h above the floor top (z = 0); returns the bottom
// height at the first impact (the contact level) and the bounces.
std::vector<Bounce> dropBall(double restitution, double h, int bounces, double& contact_level,
                             ResponseModel model = ResponseModel::NewtonCoulomb, double collision_distance = 1e-4,
                             const NativeSettings& base = NativeSettings{}) {
    const double r = 0.1;
    const double g = 9.81;
    Scene s = bareScene(collision_distance);
    const int mat = addMaterial(s, restitution, 0.5);
    addFloor(s, mat, 20.0);
    const int ball = addBody(s, "ball", Shape::sphere(r), at(Vec3(0, 0, h + r)), mat, false);
    NativeSettings ns = base;
    ns.response = model;
    auto be = makeBackend(s, ns);
    std::vector<Bounce> out;
    contact_level = -1.0;
    bool have_level = false;
    double t0 = 0, z0 = 0, v0 = 0;
    bool have_ref = false;
    const double dt = s.frame_dt;
    for (int f = 0; f < 60 * 60 && static_cast<int>(out.size()) <= bounces; ++f) {
        be->stepFrame(dt);
        const auto events = be->takeEvents();
        const BodyState st = be->bodyState(ball);
        const double z = st.pose.position.z() - r;
        const double vz = st.linear_velocity.z();
        if (!events.empty()) {
            if (!have_level) {
                have_level = true;
                // Back along the (exact) flight to the event time: the bottom height at impact.
                const double tau = be->time() - events.front().time;
                contact_level = z - vz * tau - 0.5 * g * tau * tau;
            }
            have_ref = false;
            out.push_back({});
            continue;
        }
        if (out.empty()) continue;
        Bounce& b = out.back();
        if (!have_ref) {   // z + vz^2/2g is the apex anywhere on the (exact) parabola
            have_ref = true;
            t0 = be->time();
            z0 = z;
            v0 = vz;
            b.apex = z + vz * vz / (2 * g);
        }
        if (have_ref) {
            const double tau = be->time() - t0;
            const double zp = z0 + v0 * tau - 0.5 * g * tau * tau;
            b.worst_flight_error = std::max(b.worst_flight_error, std::abs(z - zp));
            ++b.frames_in_flight;
        }
    }
    return out;
}

// In both regimes. On fixed ticks the fifth impact (at 0.28 m/s) is met at touching because its
// approach there is judged, not the approach at the tick's start (0.12 m/s, slower than gravity
// adds in a tick: judged there, the contact phase caught the ball and the apex was 0.40 mm, not
// 0.98 mm).
TEST(NativeBall, RestitutionHalfApexesFollowE2n) {
    const double e = 0.5, h = 1.0;
    for (TouchingRegime regime : {TouchingRegime::Protected, TouchingRegime::Fixed}) {
        SCOPED_TRACE(regime == TouchingRegime::Fixed ? "fixed ticks" : "default regime");
        NativeSettings ns;
        ns.touching = regime;
        double level = 0;
        const auto bounces = dropBall(e, h, 5, level, ResponseModel::NewtonCoulomb, 1e-4, ns);
        ASSERT_GE(bounces.size(), 5u);
        // The impact is resolved at touching: a gap in [0, 1e-9 x (outer radii: floor 28.3 m + ball
        // 0.1 m)], never penetrating (collision distance here 1e-4 m; before the refinement the level
        // was ~0.75e-4 m).
        EXPECT_GE(level, -1e-12);
        EXPECT_LE(level, 1e-9 * (std::sqrt(2 * 20.0 * 20.0 + 0.5 * 0.5) + 0.1) + 1e-12);
        for (int n = 1; n <= 5; ++n) {
            const double expected = std::pow(e, 2 * n) * h;
            EXPECT_NEAR(bounces[n - 1].apex, expected, 0.01 * expected) << "apex " << n;
        }
    }
}

TEST(NativeBall, FixedTicksMeetEachBounceAtTouching) {
    // Fixed ticks (native.touching=fixed) sample the floor pair at each tick's start; its impact is
    // deferred to its refined touching time and met there by a look inside the tick, so the apexes
    // follow e^(2n) h as closely as the event-driven regime's. Met at the tick's start instead
    // (native.max_tick_looks = 0: no look to defer to), the rebound leaves up to a tick early and
    // the first apex is off by about 2 % (measured 0.2551 for 0.25 with a 1 mm window).
    const double e = 0.5, h = 1.0;
    for (int looks : {64, 0}) {
        NativeSettings fixed;
        fixed.touching = TouchingRegime::Fixed;
        fixed.max_tick_looks = looks;
        double level = 0;
        const auto bounces = dropBall(e, h, 3, level, ResponseModel::NewtonCoulomb, 1e-3, fixed);
        ASSERT_GE(bounces.size(), 3u);
        double worst = 0.0;   // relative apex error
        for (int n = 1; n <= 3; ++n) {
            const double expected = std::pow(e, 2 * n) * h;
            worst = std::max(worst, std::abs(bounces[n - 1].apex - expected) / expected);
        }
        if (looks > 0) {
            EXPECT_GE(level, -1e-12);
            EXPECT_LE(level, 1e-9 * (std::sqrt(2 * 20.0 * 20.0 + 0.5 * 0.5) + 0.1) + 1e-12);
            EXPECT_LT(worst, 1e-6);
        } else {
            EXPECT_GT(worst, 1e-3);   // the case above is the deferral's doing
        }
    }
}

TEST(NativeBall, BounceLowerThanTheCollisionDistanceKeepsItsHeight) {
    // Apex e^2 h = 4.5 mm, inside a 1 cm collision window: the ball flies there freely (no
    // contact impulse catches it) and is resolved again when it touches. (Flight 61 ms: several
    // frames, so the apex is sampled.)
    const double e = 0.3, h = 0.05;
    double level = 0;
    const auto bounces = dropBall(e, h, 1, level, ResponseModel::NewtonCoulomb, 1e-2);
    ASSERT_GE(bounces.size(), 1u);
    const double expected = e * e * h;
    EXPECT_NEAR(bounces[0].apex, expected, 0.01 * expected);
}

TEST(NativeBall, BallPlacedInsideTheWindowRestsThere) {
    // Scenes place resting bodies within the collision distance (chair.json: 0.5 mm): that is
    // contact from the start, so the ball neither falls to the floor nor reports an impact.
    const double r = 0.1, cd = 1e-3, gap = 0.5e-3;
    Scene s = bareScene(cd);
    const int mat = addMaterial(s, 0.5, 0.5);
    addFloor(s, mat, 20.0);
    const int ball = addBody(s, "ball", Shape::sphere(r), at(Vec3(0, 0, r + gap)), mat, false);
    auto be = makeBackend(s);
    for (int f = 0; f < 120; ++f) be->stepFrame(s.frame_dt);
    for (const CollisionEvent& ev : be->takeEvents()) EXPECT_EQ(ev.time, 0.0) << "impact at t > 0";
    const double z = be->bodyState(ball).pose.position.z() - r;
    EXPECT_GE(z, 0.0);
    EXPECT_LE(z, cd);
    EXPECT_LT(be->bodyState(ball).linear_velocity.norm(), 1e-6);
}

TEST(NativeBall, ElasticBallKeepsItsHeightAfterTenBounces) {
    const double h = 1.0;
    double level = 0;
    const auto bounces = dropBall(1.0, h, 10, level);
    ASSERT_GE(bounces.size(), 10u);
    for (int n = 1; n <= 10; ++n) {
        EXPECT_NEAR(bounces[n - 1].apex, h, 0.01 * h) << "apex " << n;
    }
}

TEST(NativeBall, FlightBetweenBouncesIsExact) {
    double level = 0;
    const auto bounces = dropBall(0.8, 1.0, 4, level);
    ASSERT_GE(bounces.size(), 4u);
    for (std::size_t n = 0; n + 1 < bounces.size(); ++n) {
        EXPECT_GT(bounces[n].frames_in_flight, 5);
        EXPECT_LT(bounces[n].worst_flight_error, 1e-6) << "bounce " << n + 1;
    }
}

TEST(NativeBall, Vroc1995ModelBouncesWithTheMinimumElasticity) {
    const double e = 0.5, h = 1.0;
    double level = 0;
    const auto bounces = dropBall(e, h, 3, level, ResponseModel::Vroc1995);
    ASSERT_GE(bounces.size(), 3u);
    for (int n = 1; n <= 3; ++n) {
        const double expected = std::pow(e, 2 * n) * h;
        EXPECT_NEAR(bounces[n - 1].apex, expected, 0.01 * expected) << "apex " << n;
    }
}

}  // namespace
}  // namespace vroc::native::test
