// SPDX-License-Identifier: MIT
// refineContactTime against closed forms: a point falling under gravity onto a plane touches at
// t = (v + sqrt(v^2 + 2 g d)) / g; the refined time must end at a gap in [0, gap_max].
#include <gtest/gtest.h>

#include <cmath>

#include "scheduling/contact_time_refinement.h"

namespace vroc::native {
namespace {

TEST(SchedulingContactTimeRefinement, FallingPointTouchesAtTheClosedFormTime) {
    const double g = 9.81;
    for (double d0 : {1e-3, 7.5e-4, 1e-5})
        for (double v0 : {0.0, 0.5, 4.4}) {   // downward speed [m/s]
            // B falls onto A (a static plane at z = 0); the gap is B's height.
            const PartGapsFunction gaps = [&](double t) {
                const double z = d0 - v0 * t - 0.5 * g * t * t;
                return std::vector<DistanceSample>{{z, Vec3::UnitZ(), Vec3::Zero(), Vec3(0, 0, z)}};
            };
            MotionBound b;
            b.velocity = Vec3(0, 0, -v0);
            b.acceleration = Vec3(0, 0, -g);
            b.outer_radius = 0.1;
            b.inner_radius = 0.1;
            const double gap_max = 1e-10;
            const RefineResult r =
                refineContactTime(gaps, gaps(0.0), MotionBound::stationary(), b, 0.0, 1.0, gap_max);
            const double exact = (-v0 + std::sqrt(v0 * v0 + 2 * g * d0)) / g;
            ASSERT_EQ(r.state, RefineState::Touching) << "d0 " << d0 << " v0 " << v0;
            EXPECT_GE(r.gap, 0.0);
            EXPECT_LE(r.gap, gap_max);
            EXPECT_LE(r.time, exact);
            // gap = (v0 + g t) (exact - t) to first order
            EXPECT_LE(exact - r.time, gap_max / std::sqrt(v0 * v0 + 2 * g * d0) * 1.01 + 1e-15);
        }
}

TEST(SchedulingContactTimeRefinement, RisingPointThatDoesNotComeBackIsClear) {
    const double g = 9.81;
    const PartGapsFunction gaps = [&](double t) {
        const double z = 1e-3 + 2.0 * t - 0.5 * g * t * t;   // lands at t ~ 0.408 s
        return std::vector<DistanceSample>{{z, Vec3::UnitZ(), Vec3::Zero(), Vec3(0, 0, z)}};
    };
    MotionBound b;
    b.velocity = Vec3(0, 0, 2.0);
    b.acceleration = Vec3(0, 0, -g);
    b.outer_radius = b.inner_radius = 0.1;
    const RefineResult r = refineContactTime(gaps, gaps(0.0), MotionBound::stationary(), b, 0.0, 0.1, 1e-10);
    EXPECT_EQ(r.state, RefineState::Clear);
    EXPECT_EQ(r.time, 0.1);
}

}  // namespace
}  // namespace vroc::native
