// SPDX-License-Identifier: MIT
// Tracked bodies (role "tracked") in MuJoCo: a free body 1e6 times heavier than the heaviest
// virtual body, weight cancelled, qpos and qvel prescribed after every step (mjcf_writer.h). The
// closed form: a body of infinite mass moving at v strikes a free ball at rest, frictionless,
// restitution e: the ball leaves at (1 + e) v. MuJoCo has no Newton restitution: e sets the damping
// of the soft contact's spring (restitution_mapping.h), so the ball's speed is (1 + e) v only to
// the mapping's accuracy (a few per cent, docs/mujoco-backend.md). What is exact up to the finite
// mass is Galilean invariance: the strike equals the same strike seen from the plate (a real plate,
// the ball flying at -v) plus v, to about m_ball / m_plate = 1e-6 of (1 + e) v.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "mjcf_writer.h"
#include "mujoco_backend.h"
#include "test_scenes.h"
#include "vroc/core/errors.h"

namespace vroc::test {
namespace {

constexpr double kSpeed = 2.0;      // [m/s] plate speed
constexpr double kH = 1.0 / 60.0;   // [s] frame (9 MuJoCo steps of 1.85 ms)

TEST(MujocoTracked, PlateStrikingABallAtRestSendsItOffAtOnePlusETimesItsSpeed) {
    std::printf("| e | phase | ball [m/s] | (1 + e) v | static plate + v [m/s] | tracked - static - v |\n");
    for (double e : {0.5, 1.0}) {
        for (int k = 0; k < 5; ++k) {
            // Of a frame's travel, v dt; never a whole number of MuJoCo steps: a contact that starts
            // exactly touching on a step boundary is in the solve or not by rounding (its damping
            // acts at zero depth), which breaks the comparison with the static strike.
            const double phase = 0.05 + 0.2 * k;
            const double gap = (3.0 + phase) * kSpeed * kH;
            const TrackedStrike ts = trackedStrike(e, kSpeed, gap), ss = staticStrike(e, kSpeed, gap);
            auto tracked = makeMujoco(ts.scene);
            auto fixed = makeMujoco(ss.scene);
            const StrikeRun t = runStrike(*tracked, ts, kSpeed, kH, 30);
            const StrikeRun s = runStrike(*fixed, ss, 0.0, kH, 30);
            const double galilean = t.ball_velocity.x() - (s.ball_velocity.x() + kSpeed);
            std::printf("| %.1f | %.2f | %.9f | %.1f | %.9f | %+.2e |\n", e, phase, t.ball_velocity.x(), (1 + e) * kSpeed,
                        s.ball_velocity.x() + kSpeed, galilean);
            SCOPED_TRACE("e " + std::to_string(e) + " phase " + std::to_string(phase));
            // MuJoCo's restitution (the same in the static strike): -4 % to +1.3 % at e = 0.5.
            EXPECT_NEAR(t.ball_velocity.x(), (1 + e) * kSpeed, 0.05 * (1 + e) * kSpeed);
            // The plate's velocity enters the contact's damping as the ball's own would.
            EXPECT_NEAR(galilean, 0.0, 1e-5 * (1 + e) * kSpeed);
            EXPECT_LT(t.ball_velocity.tail<2>().norm() + t.ball_angular_velocity.norm(), 1e-9);
            EXPECT_EQ(t.events, 1);
            // The plate keeps its motion exactly: p0 + v t at every frame, velocity v.
            EXPECT_LT(t.plate_error, 1e-12);
            EXPECT_EQ(t.plate_velocity_error, 0.0);
        }
    }
}

// A paddle (box, long along its x axis) spins about world z through its centre at omega; its face
// sweeps into a ball at rest at radius 0.3. At the contact point p the face moves at omega x p,
// along the face normal: an impulsive strike sends the ball off at (1 + e) omega (p . axis) along
// it. Returns the ball's speed over that closed form (r from the event's point).
double paddleStrike(const Overrides& overrides) {
    const double omega = 6.0, e = 0.5;
    Scene scene = emptyScene(e, 0.0);
    scene.gravity = Vec3::Zero();
    const int ball = addBall(scene, "ball", 0.05, 0.2, Vec3(0, 0.3, 0));
    const Quat start(Eigen::AngleAxisd(-0.6, Vec3::UnitZ()));
    const int paddle = addTracked(scene, "paddle", Shape::box(Vec3(0.5, 0.02, 0.1)), at(Vec3::Zero(), start), 0,
                                  Vec3::Zero(), Vec3(0, 0, omega));
    auto backend = makeMujoco(scene, overrides);
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
    EXPECT_EQ(events.size(), 1u);
    if (events.empty()) return 0.0;
    const CollisionEvent& hit = events[0];
    const Quat q = Quat(Eigen::AngleAxisd(omega * hit.time, Vec3::UnitZ())) * start;
    const double r = hit.point.dot(q * Vec3::UnitX());
    EXPECT_GT(r, 0.25);
    EXPECT_LT(r, 0.35);
    const Vec3 expected = (1 + e) * omega * r * (q * Vec3::UnitY());
    const Vec3 got = backend->bodyState(ball).linear_velocity;
    const double angle = std::acos(std::min(1.0, got.normalized().dot(expected.normalized())));
    std::printf("paddle: ball %.6f m/s, (1 + e) omega r = %.6f m/s (%+.1f %%), r = %.4f m, angle %.2e rad\n",
                got.norm(), expected.norm(), 100 * (got.norm() / expected.norm() - 1), r, angle);
    EXPECT_LT(angle, 0.05);
    return got.norm() / expected.norm();
}

TEST(MujocoTracked, SpinningPaddleGivesTheBallItsSurfaceSpeed) {
    // The soft contact lasts about pi tc (19 ms at the default tc = 6 ms) while the paddle turns
    // 0.1 rad and the ball slides out along it: the ball leaves 15 % slow. A stiff contact is
    // nearly impulsive and converges on the closed form (with the velocity hidden from the
    // contact, as for a mocap body, the defaults give 0.62 of it).
    EXPECT_NEAR(paddleStrike({}), 1.0, 0.2);
    EXPECT_NEAR(paddleStrike({{"mujoco.contact_timeconst", "0.0005"}, {"mujoco.timestep", "0.0001"}}), 1.0, 0.02);
}

TEST(MujocoTracked, TrackedBodyIsAHeavyFreeBodyAndTheSolverScaleIgnoresIt) {
    const TrackedStrike s = trackedStrike(0.5, kSpeed, 0.1);
    auto backend = makeMujoco(s.scene);
    const mjModel& m = dynamic_cast<const mujoco::MujocoBackend&>(*backend).model();
    const int plate = mj_name2id(&m, mjOBJ_BODY, mujoco::bodyName(s.plate).c_str());
    const int ball = mj_name2id(&m, mjOBJ_BODY, mujoco::bodyName(s.ball).c_str());
    EXPECT_EQ(m.body_mass[plate], 1e6 * m.body_mass[ball]);
    const double r2 = Vec3(0.05, 0.5, 0.5).squaredNorm();   // bounding radius^2 of the plate
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(m.body_inertia[3 * plate + k], 1e6 * r2, 1e-6);
    // meaninertia: the ball's diagonal (3 m + 3 I) over all 12 dofs.
    EXPECT_NEAR(m.stat.meaninertia, (3 * 1.0 + 3 * 0.4 * 1.0 * 0.01) / 12.0, 1e-15);
}

TEST(MujocoTracked, BoxRidesARisingPlatformAtItsSpeed) {
    // Under gravity a 2 kg box rests on a tracked platform rising at 0.5 m/s (trackedLift).
    const auto lift = trackedLift([](const Scene& sc, const Overrides& o) { return makeMujoco(sc, o); }, 0.5,
                                  1.0 / 60.0, 120);
    // The soft contact holds the box 5 um deep, at exactly the platform's speed. Without the
    // platform's weight cancelled (qfrc_applied) the contact would also carry the platform's fall
    // in each step's solve and the box would sit 0.7 mm deep (measured).
    for (std::size_t f = 30; f < lift.size(); ++f) {
        EXPECT_NEAR(lift[f].gap, 0.0, 2e-5) << "frame " << f;
        EXPECT_NEAR(lift[f].box_vz, 0.5, 1e-6) << "frame " << f;
    }
}

}  // namespace
}  // namespace vroc::test
