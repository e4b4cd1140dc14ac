// SPDX-License-Identifier: MIT
// MotionBound against brute force: real rotations of real boxes and rods, real parabolas.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "scheduling/motion_bound.h"
#include "scheduling_test_geometry.h"

namespace vroc::native {
namespace {

using scheduling_testing::PosedBox;
using scheduling_testing::Trajectory;

Vec3 randomUnit(std::mt19937_64& rng) {
    std::normal_distribution<double> g;
    Vec3 v(g(rng), g(rng), g(rng));
    return v.normalized();
}

// Support function of a posed box along n: max over its corners.
double support(const PosedBox& box, const Vec3& n) {
    double best = -1e300;
    for (int i = 0; i < 8; ++i) best = std::max(best, n.dot(box.corner(i)));
    return best;
}

TEST(SchedulingMotionBound, ChordBoundsEveryPointForAnyAngle) {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int trial = 0; trial < 20000; ++trial) {
        MotionBound m;
        m.outer_radius = 0.01 + 2.0 * u(rng);
        m.angular_speed = 100.0 * u(rng);
        const double t = 0.2 * u(rng);
        const Vec3 p = randomUnit(rng) * m.outer_radius * u(rng);
        const Quat q(Eigen::AngleAxisd(m.angular_speed * t, randomUnit(rng)));
        const double moved = (q * p - p).norm();
        ASSERT_LE(moved, m.chordBound(t) * (1 + 1e-12) + 1e-15)
            << "R=" << m.outer_radius << " w=" << m.angular_speed << " t=" << t;
        ASSERT_LE(m.chordBound(t), std::min(m.angular_speed * t * m.outer_radius, 2 * m.outer_radius) * (1 + 1e-15));
    }
}

// The support plane of a rotated box never advances more than rotationApproach(t), whichever
// rotation term is selected; and Tightest is the minimum of the two.
TEST(SchedulingMotionBound, SupportGrowthUnderRotationIsBounded) {
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int trial = 0; trial < 20000; ++trial) {
        const Vec3 half(0.01 + u(rng), 0.01 + u(rng), 0.01 + 0.02 * u(rng));   // slabs and rods too
        MotionBound m;
        m.outer_radius = half.norm();
        m.inner_radius = half.minCoeff();
        m.angular_speed = 60.0 * u(rng);
        const double t = 0.1 * u(rng);
        const Quat q0(Eigen::AngleAxisd(2 * std::numbers::pi * u(rng), randomUnit(rng)));
        const Quat q1 = Quat(Eigen::AngleAxisd(m.angular_speed * t, randomUnit(rng))) * q0;
        const PosedBox before{Vec3::Zero(), q0.toRotationMatrix(), half};
        const PosedBox after{Vec3::Zero(), q1.toRotationMatrix(), half};
        const Vec3 n = randomUnit(rng);
        const double growth = support(after, n) - support(before, n);
        for (RotationTerm term : {RotationTerm::Tightest, RotationTerm::PaperMargin, RotationTerm::RateOnly}) {
            m.rotation_term = term;
            ASSERT_LE(growth, m.rotationApproach(t) + 1e-12)
                << "half=" << half.transpose() << " w=" << m.angular_speed << " t=" << t
                << " term=" << static_cast<int>(term);
        }
        m.rotation_term = RotationTerm::Tightest;
        EXPECT_DOUBLE_EQ(m.rotationApproach(t), t > 0 && m.angular_speed > 0
                                                    ? std::min(m.chordBound(t), m.rotationMargin())
                                                    : 0.0);
    }
}

// Slender rod (the anchors' stress case): the paper's margin R − r is almost R and does not
// shrink with the step, while the rate term does; Tightest picks the rate term for short steps.
TEST(SchedulingMotionBound, SlenderRodPrefersRateTermForShortSteps) {
    MotionBound rod;
    rod.outer_radius = 0.5;
    rod.inner_radius = 0.005;
    rod.angular_speed = 50.0;
    EXPECT_DOUBLE_EQ(rod.rotationMargin(), 0.495);
    const double t = 1e-3;
    EXPECT_NEAR(rod.rotationApproach(t), 2 * 0.5 * std::sin(0.5 * 50 * t), 1e-15);
    EXPECT_LT(rod.rotationApproach(t), 0.03);
    EXPECT_DOUBLE_EQ(rod.rotationApproach(1.0), 0.495);   // a long step: the margin is tighter
}

TEST(SchedulingMotionBound, ApproachBoundsTranslationAndRotationOfBoxes) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int trial = 0; trial < 5000; ++trial) {
        Trajectory tr;
        tr.v = Vec3(u(rng), u(rng), u(rng)) * 5.0;
        tr.a = Vec3(u(rng), u(rng), u(rng)) * 10.0;
        tr.omega = Vec3(u(rng), u(rng), u(rng)) * 20.0;
        tr.q0 = Quat(Eigen::AngleAxisd(3.0 * u(rng), randomUnit(rng)));
        const Vec3 half = Vec3(1.01 + u(rng), 1.01 + u(rng), 1.01 + u(rng)) * 0.2;
        MotionBound m{tr.v, tr.a, tr.omega.norm(), half.norm(), half.minCoeff()};
        const double t = 0.1 * (1.0 + u(rng));
        const PosedBox b0{tr.center(0), tr.orientation(0).toRotationMatrix(), half};
        const PosedBox bt{tr.center(t), tr.orientation(t).toRotationMatrix(), half};
        const Vec3 n = randomUnit(rng);
        ASSERT_LE(support(bt, n) - support(b0, n), m.approachBound(n, t) + 1e-12) << tr.describe();
        for (int i = 0; i < 8; ++i) {
            ASSERT_LE((bt.corner(i) - b0.corner(i)).norm(), m.maxDisplacement(t) + 1e-12) << tr.describe();
        }
    }
}

TEST(SchedulingMotionBound, SweptAabbContainsTheBodyAtEverySampledTime) {
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int trial = 0; trial < 500; ++trial) {
        Trajectory tr;
        tr.c0 = Vec3(u(rng), u(rng), u(rng));
        tr.v = Vec3(u(rng), u(rng), u(rng)) * 3.0;
        tr.a = Vec3(0, 0, -9.81) + Vec3(u(rng), u(rng), u(rng));
        tr.omega = Vec3(u(rng), u(rng), u(rng)) * 30.0;
        tr.q0 = Quat(Eigen::AngleAxisd(3.0 * u(rng), randomUnit(rng)));
        const Vec3 half = Vec3(1.01 + u(rng), 1.01 + u(rng), 1.01 + u(rng)) * 0.1;
        const MotionBound m{tr.v, tr.a, tr.omega.norm(), half.norm(), half.minCoeff()};
        const double h = 0.5 * (1.0 + u(rng));
        const PosedBox b0{tr.center(0), tr.orientation(0).toRotationMatrix(), half};
        Aabb start{Vec3::Constant(1e300), Vec3::Constant(-1e300)};
        for (int i = 0; i < 8; ++i) {
            start.lower = start.lower.cwiseMin(b0.corner(i));
            start.upper = start.upper.cwiseMax(b0.corner(i));
        }
        const Aabb swept = m.sweptAabb(start, h);
        for (int k = 0; k <= 200; ++k) {
            const double t = h * k / 200.0;
            const PosedBox bt{tr.center(t), tr.orientation(t).toRotationMatrix(), half};
            for (int i = 0; i < 8; ++i) {
                const Vec3 p = bt.corner(i);
                ASSERT_TRUE((p.array() >= swept.lower.array() - 1e-12).all() &&
                            (p.array() <= swept.upper.array() + 1e-12).all())
                    << tr.describe() << " half=" << half.transpose() << " h=" << h << " t=" << t;
            }
        }
    }
}

TEST(SchedulingMotionBound, AdvancedMovesVelocityAlongTheParabola) {
    const MotionBound m{Vec3(1, 2, 3), Vec3(0, 0, -9.81), 4.0, 0.5, 0.1};
    const MotionBound later = m.advanced(0.25);
    EXPECT_TRUE(later.velocity.isApprox(Vec3(1, 2, 3 - 9.81 * 0.25)));
    const Vec3 n = Vec3(0, 0, 1);
    // Translation from 0 to 0.25 then 0.25 to 0.5 adds up to 0 to 0.5.
    EXPECT_NEAR(m.translationAlong(n, 0.25) + later.translationAlong(n, 0.25), m.translationAlong(n, 0.5), 1e-14);
    EXPECT_TRUE(m.valid());
    MotionBound bad = m;
    bad.angular_speed = std::nan("");
    EXPECT_FALSE(bad.valid());
    // A static infinite body (a plane): no rotation, no NaN from 0 * inf.
    MotionBound plane;
    plane.outer_radius = std::numeric_limits<double>::infinity();
    EXPECT_TRUE(plane.valid());
    EXPECT_EQ(plane.approachBound(n, 1.0), 0.0);
}

}  // namespace
}  // namespace vroc::native
