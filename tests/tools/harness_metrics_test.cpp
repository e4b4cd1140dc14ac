// SPDX-License-Identifier: MIT
// Harness metric functions against hand computations.
#include <gtest/gtest.h>

#include <cmath>

#include "vroc/core/mass_properties.h"
#include "vroc/harness/documents/series_tools.h"
#include "vroc/harness/metrics/divergence.h"
#include "vroc/harness/metrics/event_timing.h"
#include "vroc/harness/metrics/invariants.h"
#include "vroc/harness/statistics/pareto.h"
#include "vroc/harness/statistics/timing_stats.h"

namespace vroc::harness {
namespace {

TEST(HarnessTiming, NearestRankPercentiles) {
    std::vector<double> s;
    for (int i = 10; i >= 1; --i) s.push_back(i);   // 1..10, unsorted
    EXPECT_EQ(percentile(s, 50), 5);
    EXPECT_EQ(percentile(s, 90), 9);
    EXPECT_EQ(percentile(s, 99), 10);
    EXPECT_EQ(percentile(s, 0), 1);
    EXPECT_EQ(percentile({}, 50), 0);
}

TEST(HarnessTiming, SummaryAndRealTimeFactor) {
    // 4 steps of 1, 2, 3, 4 ms covering 0.1 s simulated: wall 10 ms, RTF 10.
    const TimingSummary t = summarizeTiming({1e-3, 2e-3, 3e-3, 4e-3}, 0.1);
    EXPECT_DOUBLE_EQ(t.p50_us, 2000);
    EXPECT_DOUBLE_EQ(t.p99_us, 4000);
    EXPECT_NEAR(t.mean_us, 2500, 1e-9);
    EXPECT_NEAR(t.real_time_factor, 10, 1e-12);
    EXPECT_NEAR(t.wall_per_sim_s, 0.1, 1e-12);
}

TEST(HarnessTiming, HistogramBins) {
    const Histogram h = histogram({0, 1, 1, 2, 3, 4}, 4);   // bins [0,1) [1,2) [2,3) [3,4]
    ASSERT_EQ(h.counts.size(), 4u);
    EXPECT_EQ(h.counts, (std::vector<double>{1, 2, 1, 2}));
    EXPECT_DOUBLE_EQ(h.centers[0], 0.5);
    EXPECT_DOUBLE_EQ(h.centers[3], 3.5);
}

TEST(HarnessInvariants, SphereByHand) {
    Scene scene;
    scene.gravity = Vec3(0, 0, -10);
    Body b;
    b.shape = Shape::sphere(0.5);
    b.mass_properties = massProperties(b.shape, 2.0);   // I = 2/5 m r^2 = 0.2
    scene.bodies.push_back(b);
    BodyState s;
    s.pose.position = Vec3(1, 0, 3);
    s.linear_velocity = Vec3(0, 2, 0);
    s.angular_velocity = Vec3(0, 0, 5);
    const Invariants inv = computeInvariants(scene, std::vector<BodyState>{s});
    EXPECT_NEAR(inv.kinetic, 0.5 * 2 * 4 + 0.5 * 0.2 * 25, 1e-12);   // 4 + 2.5
    EXPECT_NEAR(inv.potential, 2 * 10 * 3, 1e-12);
    EXPECT_TRUE(inv.linear_momentum.isApprox(Vec3(0, 4, 0)));
    // L = x × m v + I ω = (1,0,3) × (0,4,0) + (0,0,1) = (-12, 0, 4) + (0, 0, 1)
    EXPECT_TRUE(inv.angular_momentum.isApprox(Vec3(-12, 0, 5), 1e-12)) << inv.angular_momentum.transpose();
}

TEST(HarnessDivergence, HorizonAndFtleOfAnExponential) {
    std::vector<double> t, spread;
    for (int i = 0; i <= 100; ++i) {
        t.push_back(0.1 * i);
        spread.push_back(1e-9 * std::exp(2.0 * t.back()));   // λ = 2 /s
    }
    // 1e-9 e^{2t} > 1e-3  <=>  t > ln(1e6)/2 = 6.9078 -> first sample t = 7.0
    ASSERT_TRUE(horizon(t, spread, 1e-3).has_value());
    EXPECT_NEAR(*horizon(t, spread, 1e-3), 7.0, 1e-12);
    EXPECT_FALSE(horizon(t, spread, 1.0).has_value());
    EXPECT_NEAR(*ftle(t, spread, 1e-8, 1e-3), 2.0, 1e-9);
}

TEST(HarnessDivergence, SignificanceAboveBothFloors) {
    const std::vector<double> t = {0, 1, 2, 3}, d = {0, 1, 3, 5}, fa = {1, 1, 1, 1}, fb = {0, 2, 4, 4};
    const Significance s = significantDivergence(d, fa, fb, t);
    ASSERT_TRUE(s.first_time.has_value());
    EXPECT_EQ(*s.first_time, 3);   // only 5 > max(1, 4)
    EXPECT_DOUBLE_EQ(s.fraction, 0.25);
}

TEST(HarnessDivergence, AngleErrorTreatsQAndMinusQAlike) {
    Scene scene;
    scene.bodies.push_back(Body{});
    BodyState a, b;
    b.pose.orientation = Quat(Eigen::AngleAxisd(0.3, Vec3::UnitZ()));
    b.pose.orientation.coeffs() *= -1;
    EXPECT_NEAR(maxAngleError(scene, std::vector<BodyState>{a}, std::vector<BodyState>{b}), 0.3, 1e-12);
}

TEST(HarnessEvents, ImpactsMergeContactPointsOfOneImpact) {
    auto ev = [](double t, int a, int b) { CollisionEvent e; e.time = t; e.body_a = a; e.body_b = b; return e; };
    // Body 1 hits ground (0) with 4 contact points at 0.5 s, again at 1.0 s; body 2 at 0.7 s.
    const std::vector<CollisionEvent> events = {ev(0.5, 0, 1), ev(0.5, 0, 1), ev(0.504, 0, 1), ev(0.7, 0, 2), ev(0.51, 0, 1), ev(1.0, 0, 1)};
    EXPECT_EQ(impactTimes(events, 1, 0.02), (std::vector<double>{0.5, 1.0}));
    EXPECT_EQ(impactTimes(events, 2, 0.02), (std::vector<double>{0.7}));
}

TEST(HarnessEvents, RestTimeIsTheStartOfTheLastRestingStretch) {
    Scene scene;
    scene.bodies.push_back(Body{});
    RunTrace t;
    const double speeds[] = {1.0, 0.0, 0.5, 0.001, 0.0};
    for (int i = 0; i < 5; ++i) {
        BodyState s;
        s.linear_velocity = Vec3(speeds[i], 0, 0);
        t.times.push_back(i);
        t.states.push_back({s});
    }
    ASSERT_TRUE(restTime(scene, t).has_value());
    EXPECT_EQ(*restTime(scene, t), 3);
}

TEST(HarnessPareto, FrontByHand) {
    // (cost, error): a(1,10) b(2,5) c(3,7) d(4,1) e(2,5) f(5,1): front a, b, d.
    const std::vector<CostError> p = {{1, 10}, {2, 5}, {3, 7}, {4, 1}, {2, 5}, {5, 1}, {NAN, 0}};
    EXPECT_EQ(paretoFront(p), (std::vector<std::size_t>{0, 1, 3}));
}

TEST(HarnessPareto, ConvergenceOrderOfAQuadraticError) {
    std::vector<double> dt, err;
    for (double h = 1.0 / 60; h > 1e-4; h /= 2) {
        dt.push_back(h);
        err.push_back(3.0 * h * h);
    }
    EXPECT_NEAR(*convergenceOrder(dt, err), 2.0, 1e-9);
}

TEST(HarnessSeries, StrideKeepsEndsAndBound) {
    const auto idx = strideIndices(1001, 100);
    EXPECT_LE(idx.size(), 101u);
    EXPECT_EQ(idx.front(), 0u);
    EXPECT_EQ(idx.back(), 1000u);
    EXPECT_EQ(strideIndices(5, 100), (std::vector<std::size_t>{0, 1, 2, 3, 4}));
}

}  // namespace
}  // namespace vroc::harness
