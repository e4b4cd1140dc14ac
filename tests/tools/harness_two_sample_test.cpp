// SPDX-License-Identifier: MIT
// The ensemble statistics (two_sample_tests.h) against independent answers: the energy distance of
// scalars against twice the integrated squared CDF difference (Székely's identity), Wasserstein-1
// against the sorted-pairs formula, the permutation test's extremes, Holm against a hand example.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "vroc/harness/two_sample_tests.h"

namespace vroc::harness {
namespace {

std::vector<Sample> scalars(const std::vector<double>& v) {
    std::vector<Sample> out;
    for (double x : v) out.push_back({x});
    return out;
}

// 2 * integral of (F_n - G_m)^2 over the line, by sweeping the merged sorted points.
double twiceIntegratedSquaredCdfGap(std::vector<double> x, std::vector<double> y) {
    std::vector<double> all = x;
    all.insert(all.end(), y.begin(), y.end());
    std::sort(all.begin(), all.end());
    double sum = 0;
    for (std::size_t k = 0; k + 1 < all.size(); ++k) {
        const double mid = 0.5 * (all[k] + all[k + 1]);
        const double f = double(std::count_if(x.begin(), x.end(), [&](double v) { return v <= mid; })) / double(x.size());
        const double g = double(std::count_if(y.begin(), y.end(), [&](double v) { return v <= mid; })) / double(y.size());
        sum += (f - g) * (f - g) * (all[k + 1] - all[k]);
    }
    return 2 * sum;
}

TEST(TwoSampleTests, EnergyDistanceOfScalarsIsTwiceTheIntegratedSquaredCdfGap) {
    SplitMix64 rng(7);
    std::vector<double> x, y;
    for (int i = 0; i < 23; ++i) x.push_back(rng.normal());
    for (int i = 0; i < 31; ++i) y.push_back(0.4 + 1.3 * rng.normal());
    EXPECT_NEAR(energyDistance(scalars(x), scalars(y)), twiceIntegratedSquaredCdfGap(x, y), 1e-12);
}

TEST(TwoSampleTests, EnergyDistanceOfTwoPointsIsTwiceTheirDistance) {
    // One point each: 2|a-b| - 0 - 0, in any dimension.
    EXPECT_DOUBLE_EQ(energyDistance({{0, 0, 0}}, {{3, 4, 0}}), 10.0);
    EXPECT_DOUBLE_EQ(energyDistance(scalars({1, 2, 3}), scalars({1, 2, 3})), 0.0);
}

TEST(TwoSampleTests, WassersteinOfEqualSizedSamplesPairsTheSortedValues) {
    SplitMix64 rng(11);
    std::vector<double> x, y;
    for (int i = 0; i < 40; ++i) { x.push_back(rng.normal()); y.push_back(2 * rng.uniform()); }
    std::vector<double> xs = x, ys = y;
    std::sort(xs.begin(), xs.end());
    std::sort(ys.begin(), ys.end());
    double paired = 0;
    for (std::size_t i = 0; i < xs.size(); ++i) paired += std::abs(xs[i] - ys[i]) / double(xs.size());
    EXPECT_NEAR(wasserstein1(x, y), paired, 1e-12);
    // A shift moves every quantile by the shift.
    std::vector<double> shifted = x;
    for (double& v : shifted) v += 0.25;
    EXPECT_NEAR(wasserstein1(x, shifted), 0.25, 1e-12);
}

TEST(TwoSampleTests, PermutationTestSeparatesDisjointSamplesAndNotEqualOnes) {
    SplitMix64 rng(3);
    std::vector<Sample> a, b, c;
    for (int i = 0; i < 20; ++i) {
        a.push_back({rng.normal(), rng.normal()});
        b.push_back({10 + rng.normal(), rng.normal()});
    }
    c = a;
    const PermutationTest apart = energyPermutationTest(a, b, 199, 1);
    EXPECT_DOUBLE_EQ(apart.p_value, 1.0 / 200.0);   // no permutation is as extreme as the observed split
    const PermutationTest same = energyPermutationTest(a, c, 199, 1);
    EXPECT_DOUBLE_EQ(same.statistic, 0.0);
    EXPECT_DOUBLE_EQ(same.p_value, 1.0);
    // Reproducible: the same seed gives the same p-value.
    std::vector<Sample> d;
    for (int i = 0; i < 20; ++i) d.push_back({0.3 + rng.normal(), rng.normal()});
    EXPECT_EQ(energyPermutationTest(a, d, 199, 5).p_value, energyPermutationTest(a, d, 199, 5).p_value);
}

TEST(TwoSampleTests, PermutationTestHoldsItsLevelUnderTheNull) {
    // Both samples from one distribution: p < 0.05 should happen about 5 % of the time.
    SplitMix64 rng(99);
    int rejected = 0;
    const int trials = 200;
    for (int t = 0; t < trials; ++t) {
        std::vector<Sample> x, y;
        for (int i = 0; i < 12; ++i) { x.push_back({rng.normal()}); y.push_back({rng.normal()}); }
        if (energyPermutationTest(x, y, 99, static_cast<std::uint64_t>(t)).p_value < 0.05) ++rejected;
    }
    EXPECT_LT(rejected, 25);   // binomial(200, 0.05): mean 10, P(>= 25) < 1e-4
    EXPECT_GT(rejected, 1);
}

TEST(TwoSampleTests, HolmAdjustmentMatchesTheHandExample) {
    // Sorted p: 0.01, 0.02, 0.03, 0.04 with k = 4 -> 0.04, 0.06, 0.06 (monotone), 0.06.
    const std::vector<double> adj = holmAdjusted({0.03, 0.01, 0.04, 0.02});
    EXPECT_DOUBLE_EQ(adj[1], 0.04);
    EXPECT_DOUBLE_EQ(adj[3], 0.06);
    EXPECT_DOUBLE_EQ(adj[0], 0.06);
    EXPECT_DOUBLE_EQ(adj[2], 0.06);
    EXPECT_DOUBLE_EQ(holmAdjusted({0.5, 0.9})[1], 1.0);   // capped at 1
}

TEST(TwoSampleTests, SplitMixNormalHasUnitMoments) {
    SplitMix64 rng(2026);
    const int n = 200000;
    double sum = 0, sq = 0;
    for (int i = 0; i < n; ++i) {
        const double v = rng.normal();
        sum += v;
        sq += v * v;
    }
    EXPECT_NEAR(sum / n, 0.0, 0.01);       // standard error 0.0022
    EXPECT_NEAR(sq / n, 1.0, 0.015);       // standard error 0.0032
}

}  // namespace
}  // namespace vroc::harness
