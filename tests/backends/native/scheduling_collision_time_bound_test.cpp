// SPDX-License-Identifier: MIT
// earliestCollisionTime: closed forms where the bound is exact, and a property test on random
// sphere/box trajectories where the true first contact comes from Lipschitz-safe dense sampling.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "scheduling/collision_time_bound.h"
#include "scheduling_test_geometry.h"

namespace vroc::native {
namespace {

using scheduling_testing::TestShape;
using scheduling_testing::Trajectory;

TEST(SchedulingCollisionTimeBound, HeadOnConstantVelocityIsExact) {
    const MotionBound a{Vec3(3, 0, 0), Vec3::Zero(), 0, 0.1, 0.1};
    const MotionBound b{Vec3(-1, 0, 0), Vec3::Zero(), 0, 0.2, 0.2};
    EXPECT_NEAR(earliestCollisionTime(2.0, Vec3::UnitX(), a, b, 10.0), 0.5, 1e-15);
    EXPECT_EQ(earliestCollisionTime(2.0, Vec3::UnitX(), a, b, 0.4), kNever);   // beyond horizon
    EXPECT_EQ(earliestCollisionTime(2.0, -Vec3::UnitX(), a, b, 10.0), kNever); // receding
    EXPECT_EQ(earliestCollisionTime(0.0, Vec3::UnitX(), a, b, 10.0), 0.0);
    EXPECT_EQ(earliestCollisionTime(-1.0, -Vec3::UnitX(), a, b, 10.0), 0.0);
    EXPECT_NEAR(earliestCollisionTime(2.0, a, b, 10.0), 0.5, 1e-15);   // direction-free: |v_rel| = 4
}

TEST(SchedulingCollisionTimeBound, FreeFallOntoFloorIsExact) {
    // A is the ball (normal A->B points down to the floor), B the static floor.
    const double g = 9.81;
    const MotionBound ball{Vec3::Zero(), Vec3(0, 0, -g), 0, 0.05, 0.05};
    const MotionBound floor = MotionBound::stationary();
    const Vec3 down(0, 0, -1);
    EXPECT_NEAR(earliestCollisionTime(1.0, down, ball, floor, 10.0), std::sqrt(2.0 / g), 1e-15);
    // Thrown up at 3 m/s from 0.5 m: 0.5 + 3t − g t²/2 = 0.
    const MotionBound up{Vec3(0, 0, 3), Vec3(0, 0, -g), 0, 0.05, 0.05};
    const double expect = (3 + std::sqrt(9 + 2 * g * 0.5)) / g;
    EXPECT_NEAR(earliestCollisionTime(0.5, down, up, floor, 10.0), expect, 1e-14);
}

TEST(SchedulingCollisionTimeBound, RotationPiecesAreSolvedExactly) {
    // Pure spin: rot(t) = min(|ω| R t, R − r). Gap below the margin: the rate piece decides.
    const MotionBound rod{Vec3::Zero(), Vec3::Zero(), 50.0, 0.5, 0.005};
    const MotionBound post = MotionBound::stationary();
    EXPECT_NEAR(earliestCollisionTime(0.1, Vec3::UnitX(), rod, post, 1.0), 0.1 / 25.0, 1e-16);
    // Gap above the margin R − r = 0.495: the margin caps the rotation, so never.
    EXPECT_EQ(earliestCollisionTime(0.5, Vec3::UnitX(), rod, post, 1.0), kNever);
    // With translation too: rate piece 27 t until t_s = 0.495 / 25, then 0.495 + 2 t.
    MotionBound moving = rod;
    moving.velocity = Vec3(2, 0, 0);
    const double ts = 0.495 / 25.0;
    ASSERT_LT(27.0 * ts, 0.6);   // the rate piece does not reach the gap before the switch
    EXPECT_NEAR(earliestCollisionTime(0.6, Vec3::UnitX(), moving, post, 1.0), (0.6 - 0.495) / 2.0, 1e-15);
    EXPECT_NEAR(earliestCollisionTime(0.5, Vec3::UnitX(), moving, post, 1.0), 0.5 / 27.0, 1e-15);
    // The paper's margin alone stalls for a slender rod: any gap below R − r gives time 0.
    MotionBound paper = rod;
    paper.rotation_term = RotationTerm::PaperMargin;
    EXPECT_EQ(earliestCollisionTime(0.1, Vec3::UnitX(), paper, post, 1.0), 0.0);
}

struct RandomCase {
    TestShape shape_a, shape_b;
    Trajectory ta, tb;
};

RandomCase randomCase(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::uniform_real_distribution<double> p(0.0, 1.0);
    RandomCase c;
    auto shape = [&] {
        TestShape s;
        if (p(rng) < 0.4) s.radius = 0.05 + 0.3 * p(rng);
        else s.half_extents = Vec3(0.02 + 0.3 * p(rng), 0.02 + 0.3 * p(rng), 0.02 + 0.3 * p(rng));
        return s;
    };
    c.shape_a = shape();
    c.shape_b = shape();
    c.ta.c0 = Vec3(u(rng), u(rng), u(rng));
    c.tb.c0 = c.ta.c0 + Vec3(u(rng), u(rng), u(rng)).normalized() * (1.0 + p(rng));
    // Aim roughly at each other so most cases do collide.
    const Vec3 towards = (c.tb.c0 - c.ta.c0).normalized();
    c.ta.v = towards * 4.0 * p(rng) + Vec3(u(rng), u(rng), u(rng));
    c.tb.v = -towards * 4.0 * p(rng) + Vec3(u(rng), u(rng), u(rng));
    c.ta.a = Vec3(u(rng), u(rng), u(rng)) * 10.0;
    c.tb.a = p(rng) < 0.5 ? c.ta.a : Vec3(u(rng), u(rng), u(rng)) * 10.0;
    c.ta.omega = Vec3(u(rng), u(rng), u(rng)) * 20.0 * p(rng);
    c.tb.omega = Vec3(u(rng), u(rng), u(rng)) * 20.0 * p(rng);
    c.ta.q0 = Quat(Eigen::AngleAxisd(3.0 * u(rng), Vec3(u(rng), u(rng), u(rng)).normalized()));
    c.tb.q0 = Quat(Eigen::AngleAxisd(3.0 * u(rng), Vec3(u(rng), u(rng), u(rng)).normalized()));
    return c;
}

MotionBound boundOf(const TestShape& s, const Trajectory& t) {
    return {t.v, t.a, t.omega.norm(), s.outerRadius(), s.innerRadius()};
}

// The bound is never later than the true first time the distance reaches the collision distance.
TEST(SchedulingCollisionTimeBound, NeverLaterThanTrueContactOnRandomTrajectories) {
    std::mt19937_64 rng(42);
    const double cd = 1e-3;
    const double horizon = 1.0;
    int checked = 0, collided = 0, skipped = 0;
    double tightness_sum = 0.0;
    for (int trial = 0; trial < 400; ++trial) {
        const RandomCase c = randomCase(rng);
        const auto d0 = scheduling_testing::shapeDistance(c.shape_a, c.ta, c.shape_b, c.tb, 0.0);
        if (d0.distance <= cd) continue;
        const MotionBound ma = boundOf(c.shape_a, c.ta), mb = boundOf(c.shape_b, c.tb);
        const double lipschitz = (c.ta.v - c.tb.v).norm() + (c.ta.a - c.tb.a).norm() * horizon +
                                 ma.angular_speed * ma.outer_radius + mb.angular_speed * mb.outer_radius;
        auto f = [&](double t) { return scheduling_testing::shapeDistance(c.shape_a, c.ta, c.shape_b, c.tb, t).distance; };
        const double truth = scheduling_testing::firstCrossing(f, 0.0, horizon, cd, lipschitz, horizon / 2000.0);
        if (std::isnan(truth)) { ++skipped; continue; }
        const double with_normal = earliestCollisionTime(d0.distance - cd, d0.normal, ma, mb, horizon);
        const double free_dir = earliestCollisionTime(d0.distance - cd, ma, mb, horizon);
        ++checked;
        const std::string config = "shapes r=" + std::to_string(c.shape_a.radius) + "/" +
                                   std::to_string(c.shape_b.radius) + " A=" + c.ta.describe() +
                                   " B=" + c.tb.describe();
        ASSERT_LE(with_normal, truth + 1e-9) << config;
        ASSERT_LE(free_dir, truth + 1e-9) << config;
        ASSERT_GE(with_normal, free_dir * (1 - 1e-12) - 1e-12)
            << "projected bound looser than the direction-free one: " << config;
        if (truth < kNever) {
            ++collided;
            tightness_sum += with_normal / std::max(truth, 1e-12);
        }
    }
    EXPECT_GE(checked, 300);
    EXPECT_GE(collided, 100);
    EXPECT_LE(skipped, 4);
    std::printf("[info] %d cases, %d collide, mean bound/true time %.3f, %d skipped\n", checked,
                collided, tightness_sum / std::max(collided, 1), skipped);
}

}  // namespace
}  // namespace vroc::native
