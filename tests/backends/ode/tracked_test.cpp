// SPDX-License-Identifier: MIT
// Tracked bodies (role "tracked") as ODE kinematic bodies. The closed form: a body of infinite mass
// moving at v strikes a free ball at rest, frictionless, restitution e: the ball leaves at
// (1 + e) v. ODE finds the contact once the plate overlaps the ball (by up to v h) and its bounce
// row sets the separating speed to max(e x approach speed, erp x depth / h) (ODE's contact joint),
// which is e v here (erp depth / h <= 0.2 v < e v), so the ball leaves at (1 + e) v wherever the
// step grid puts the contact, softened only by ODE's constraint force mixing: the row solves
// (1/m + cfm/h) lambda = m (1 + e) v / m, so the ball leaves at (1 + e) v / (1 + cfm m / h)
// (6e-9 below (1 + e) v at cfm 1e-10, m = 1 kg, h = 1/60 s). Held also against the same strike seen from the plate (a real plate,
// the ball flying at -v), which Galilean invariance makes identical.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ode_test_scenes.h"
#include "vroc/core/errors.h"

namespace vroc::test {
namespace {

constexpr double kSpeed = 2.0;      // [m/s] plate speed
constexpr double kH = 1.0 / 60.0;   // [s] frame = ODE step (ode.substeps 1)
constexpr double kCfm = 1e-10;      // ODE's default CFM in double precision (ode.cfm)
constexpr double kBallMass = 1.0;   // [kg] trackedStrike's ball

TEST(OdeTracked, PlateStrikingABallAtRestSendsItOffAtOnePlusETimesItsSpeed) {
    std::printf("| stepper | e | phase | ball [m/s] | (1 + e) v / (1 + cfm m / h) | static plate + v [m/s] |\n");
    for (const char* stepper : {"quickstep", "step"}) {
        for (double e : {0.5, 1.0}) {
            for (int k = 0; k < 10; ++k) {
                const double phase = 0.1 * k;   // of a step's travel, v h
                const double gap = (3.0 + phase) * kSpeed * kH;
                const TrackedStrike ts = trackedStrike(e, kSpeed, gap), ss = staticStrike(e, kSpeed, gap);
                auto tracked = makeOde(ts.scene, {{"ode.stepper", stepper}});
                auto fixed = makeOde(ss.scene, {{"ode.stepper", stepper}});
                const StrikeRun t = runStrike(*tracked, ts, kSpeed, kH, 30);
                const StrikeRun s = runStrike(*fixed, ss, 0.0, kH, 30);
                const double closed = (1 + e) * kSpeed / (1 + kCfm * kBallMass / kH);
                if (k % 3 == 0)
                    std::printf("| %s | %.1f | %.1f | %.12f | %.12f | %.12f |\n", stepper, e, phase, t.ball_velocity.x(),
                                closed, s.ball_velocity.x() + kSpeed);
                SCOPED_TRACE(std::string(stepper) + " e " + std::to_string(e) + " phase " + std::to_string(phase));
                // dWorldStep solves the row exactly; QuickStep's 20 SOR sweeps leave ~1e-10.
                EXPECT_NEAR(t.ball_velocity.x(), closed, 1e-9);
                EXPECT_LT(t.ball_velocity.tail<2>().norm() + t.ball_angular_velocity.norm(), 1e-12);
                EXPECT_NEAR(t.ball_velocity.x(), s.ball_velocity.x() + kSpeed, 1e-9);
                EXPECT_EQ(t.events, 1);
                // The plate keeps its motion exactly: p0 + v t at every frame, velocity v.
                EXPECT_LT(t.plate_error, 1e-12);
                EXPECT_EQ(t.plate_velocity_error, 0.0);
            }
        }
    }
}

TEST(OdeTracked, SpinningPaddleGivesTheBallItsSurfaceSpeed) {
    // A paddle (box, long along its x axis) spins about world z through its centre at omega; its
    // face sweeps into a ball at rest at radius 0.3. At the contact point p the face moves at
    // omega x p, along the face normal: the ball leaves at (1 + e) omega (p . axis) along it.
    const double omega = 6.0, e = 0.5;
    Scene scene = emptyScene(e, 0.0);
    scene.gravity = Vec3::Zero();
    const int ball = addBall(scene, "ball", 0.05, 0.2, Vec3(0, 0.3, 0));
    const Quat start(Eigen::AngleAxisd(-0.6, Vec3::UnitZ()));
    const int paddle = addTracked(scene, "paddle", Shape::box(Vec3(0.5, 0.02, 0.1)), at(Vec3::Zero(), start), 0,
                                  Vec3::Zero(), Vec3(0, 0, omega));
    auto backend = makeOde(scene);
    std::vector<CollisionEvent> events;
    const double h = 1.0 / 240.0;
    for (int f = 0; f < 80; ++f) {
        backend->stepFrame(h);
        for (const CollisionEvent& ev : backend->takeEvents()) events.push_back(ev);
        const BodyState p = backend->bodyState(paddle);
        const Quat expected = Quat(Eigen::AngleAxisd(omega * backend->time(), Vec3::UnitZ())) * start;
        EXPECT_LT(p.pose.orientation.angularDistance(expected), 1e-12);
        EXPECT_LT(p.pose.position.norm(), 1e-15);
        EXPECT_EQ(p.angular_velocity, Vec3(0, 0, omega));
    }
    ASSERT_EQ(events.size(), 1u);
    const CollisionEvent& hit = events[0];
    // The paddle's pose at the start of the step that pushed (ODE's contact is found there).
    const Quat q = Quat(Eigen::AngleAxisd(omega * (hit.time - h), Vec3::UnitZ())) * start;
    const double r = hit.point.dot(q * Vec3::UnitX());
    const Vec3 expected = (1 + e) * omega * r * (q * Vec3::UnitY());
    const Vec3 got = backend->bodyState(ball).linear_velocity;
    const double angle = std::acos(std::min(1.0, got.normalized().dot(expected.normalized())));
    std::printf("paddle: ball %.6f m/s, (1 + e) omega r = %.6f m/s, r = %.4f m, angle %.2e rad\n", got.norm(),
                expected.norm(), r, angle);
    // r from the event's point, which is ODE's contact point: the bounce row's own lever arm.
    EXPECT_NEAR(got.norm(), expected.norm(), 1e-6 * expected.norm());
    EXPECT_LT(angle, 1e-6);
    EXPECT_GT(r, 0.25);
    EXPECT_LT(r, 0.35);
}

TEST(OdeTracked, BoxRidesARisingPlatformAtItsSpeed) {
    // Under gravity a 2 kg box rests on a tracked platform rising at 0.5 m/s (trackedLift).
    const auto lift = trackedLift([](const Scene& sc, const Overrides& o) { return makeOde(sc, o); }, 0.5,
                                  1.0 / 60.0, 120);
    // ODE acts on the contact a step after it finds it, so the platform first pushes 10 mm into
    // the box, which ERP (0.2 of the overlap per step) takes out within 30 frames. At 1.1 s
    // dCollideBoxBox drops two of the four corner points of the exactly touching faces for two
    // steps (ODE's box-box clipping at zero depth): the box tips 5 mrad and sinks 1.5 mm, then
    // recovers the same way. It rides the platform: same speed on average, back to touching.
    for (std::size_t f = 30; f < lift.size(); ++f) {
        EXPECT_GT(lift[f].gap, -2e-3) << "frame " << f;
        EXPECT_LT(lift[f].gap, 1e-5) << "frame " << f;
        EXPECT_NEAR(lift[f].box_vz, 0.5, 0.07) << "frame " << f;
    }
    EXPECT_NEAR(lift.back().gap, 0.0, 1e-5);
    EXPECT_NEAR(lift.back().box_vz, 0.5, 1e-5);
}

}  // namespace
}  // namespace vroc::test
