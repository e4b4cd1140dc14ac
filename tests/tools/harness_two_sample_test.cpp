// SPDX-License-Identifier: MIT
// The ensemble statistics (two_sample_tests.h) against independent answers: the energy distance
// against a brute-force U-statistic and, for scalars, against Székely's identity (V = 2 * integral
// of the squared CDF difference) less the V-statistic's diagonal terms (Gini's mean differences from
// the sorted values); its mean over draws from one distribution against 0 (and the V-statistic's
// against its closed-form bias); Wasserstein-1 against the sorted-pairs formula; the permutation
// tests' extremes and level; the sign-flip test against exhaustive enumeration; Holm by hand.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "vroc/harness/statistics/two_sample_tests.h"

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

// Gini's mean difference, the mean of |x_i - x_j| over i != j, from the sorted values:
// 2 / (n (n - 1)) * sum_i (2i - n - 1) x_(i), i = 1..n.
double giniMeanDifference(std::vector<double> x) {
    std::sort(x.begin(), x.end());
    const double n = double(x.size());
    double sum = 0;
    for (std::size_t i = 0; i < x.size(); ++i) sum += (2.0 * double(i + 1) - n - 1) * x[i];
    return 2 * sum / (n * (n - 1));
}

// The definition, term by term: 2 mean|x_i - y_j| - mean_{i != j}|x_i - x_j| - mean_{i != j}|y_i - y_j|.
double bruteForceU(const std::vector<Sample>& x, const std::vector<Sample>& y) {
    auto dist = [](const Sample& a, const Sample& b) {
        double s = 0;
        for (std::size_t k = 0; k < a.size(); ++k) s += (a[k] - b[k]) * (a[k] - b[k]);
        return std::sqrt(s);
    };
    auto within = [&](const std::vector<Sample>& v) {
        double s = 0;
        int pairs = 0;
        for (std::size_t i = 0; i < v.size(); ++i)
            for (std::size_t j = 0; j < v.size(); ++j)
                if (i != j) {
                    s += dist(v[i], v[j]);
                    ++pairs;
                }
        return s / pairs;
    };
    double cross = 0;
    for (const Sample& a : x)
        for (const Sample& b : y) cross += dist(a, b);
    return 2 * cross / double(x.size() * y.size()) - within(x) - within(y);
}

TEST(TwoSampleTests, EnergyDistanceIsTheUStatisticByBruteForce) {
    SplitMix64 rng(17);
    std::vector<Sample> x, y;
    for (int i = 0; i < 5; ++i) x.push_back({rng.normal(), rng.normal(), rng.normal()});
    for (int i = 0; i < 7; ++i) y.push_back({0.5 + rng.normal(), rng.normal(), 2 * rng.normal()});
    EXPECT_NEAR(energyDistance(x, y), bruteForceU(x, y), 1e-12);
    EXPECT_NEAR(energyDistance(scalars({0.1, 0.7, -0.3}), scalars({1, 2})),
                bruteForceU(scalars({0.1, 0.7, -0.3}), scalars({1, 2})), 1e-12);
}

TEST(TwoSampleTests, EnergyDistanceOfScalarsIsSzekelysIdentityLessTheDiagonal) {
    // V = 2 * integral (F_n - G_m)^2 (Székely); U = V - GMD(x) / n - GMD(y) / m.
    SplitMix64 rng(7);
    std::vector<double> x, y;
    for (int i = 0; i < 23; ++i) x.push_back(rng.normal());
    for (int i = 0; i < 31; ++i) y.push_back(0.4 + 1.3 * rng.normal());
    const double expected =
        twiceIntegratedSquaredCdfGap(x, y) - giniMeanDifference(x) / 23 - giniMeanDifference(y) / 31;
    EXPECT_NEAR(energyDistance(scalars(x), scalars(y)), expected, 1e-12);
}

TEST(TwoSampleTests, EnergyDistanceOfTwoPointsIsTwiceTheirDistance) {
    // Each sample one point, twice: 2|a-b| - 0 - 0, in any dimension.
    EXPECT_DOUBLE_EQ(energyDistance({{0, 0, 0}, {0, 0, 0}}, {{3, 4, 0}, {3, 4, 0}}), 10.0);
    // Two copies of {1, 2, 3}: 2 * 8/9 - 4/3 - 4/3 = -8/9. The U-statistic is not clamped at 0.
    EXPECT_NEAR(energyDistance(scalars({1, 2, 3}), scalars({1, 2, 3})), -8.0 / 9.0, 1e-15);
    EXPECT_THROW(energyDistance(scalars({1}), scalars({1, 2})), std::invalid_argument);
}

TEST(TwoSampleTests, EnergyDistanceIsUnbiasedForTwoSamplesOfOneDistribution) {
    // n = m = 32 standard normals, 4000 draws. E[U] = 0. The V-statistic's mean is
    // (1/n + 1/m) E|X - X'| = (2/32) (2/sqrt(pi)) = 0.0705: 7 % of the spread, the bias U removes.
    SplitMix64 rng(2023);
    const int draws = 4000, n = 32;
    double sum_u = 0, sum_v = 0;
    for (int d = 0; d < draws; ++d) {
        std::vector<double> x, y;
        for (int i = 0; i < n; ++i) {
            x.push_back(rng.normal());
            y.push_back(rng.normal());
        }
        sum_u += energyDistance(scalars(x), scalars(y));
        sum_v += twiceIntegratedSquaredCdfGap(x, y);  // the V-statistic (Székely's identity)
    }
    // The statistic's standard deviation at n = 32 is about 0.06, so its mean over 4000 draws has a
    // standard error of about 0.001: the tolerance is 4 of them, the V-statistic's bias 70.
    EXPECT_NEAR(sum_u / draws, 0.0, 0.004);
    EXPECT_NEAR(sum_v / draws, (2.0 / n) * (2.0 / std::sqrt(M_PI)), 0.004);
}

TEST(TwoSampleTests, MarginalWassersteinIsTheShiftOfATranslatedEnsemble) {
    SplitMix64 rng(13);
    std::vector<Sample> x, y;
    for (int i = 0; i < 20; ++i) {
        x.push_back({rng.normal(), rng.normal(), rng.normal()});
        y.push_back({x.back()[0] + 0.3, x.back()[1] - 0.4, x.back()[2]});
    }
    EXPECT_NEAR(marginalWasserstein1(x, y), 0.5, 1e-12);
    std::vector<double> a, b;
    for (int i = 0; i < 9; ++i) {
        a.push_back(rng.normal());
        b.push_back(rng.uniform());
    }
    EXPECT_NEAR(marginalWasserstein1(scalars(a), scalars(b)), wasserstein1(a, b), 1e-15);
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
    EXPECT_LT(same.statistic, 0.0);  // two copies: closer than two draws of one ensemble
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
    EXPECT_LT(rejected, 25);  // binomial(200, 0.05): mean 10, P(>= 25) < 1e-4
    EXPECT_GT(rejected, 1);
}

TEST(TwoSampleTests, SignFlipTestMatchesExhaustiveEnumeration) {
    // n = 10 paired differences: all 1024 sign vectors give the exact p-value.
    SplitMix64 rng(31);
    std::vector<double> a, b, d;
    for (int i = 0; i < 10; ++i) {
        a.push_back(rng.normal());
        b.push_back(a.back() - 0.3 + rng.normal());
        d.push_back(a.back() - b.back());
    }
    double observed = 0;
    for (double v : d) observed += v / 10;
    int as_large = 0;
    for (int signs = 0; signs < 1024; ++signs) {
        double mean = 0;
        for (int k = 0; k < 10; ++k) mean += ((signs >> k) & 1 ? d[k] : -d[k]) / 10;
        if (std::abs(mean) >= std::abs(observed) - 1e-12) ++as_large;
    }
    const double exact = as_large / 1024.0;
    const PairedTest t = pairedSignFlipTest(a, b, 40000, 3);
    EXPECT_EQ(t.pairs, 10u);
    EXPECT_NEAR(t.mean_difference, observed, 1e-12);
    EXPECT_NEAR(t.p_value, exact, 0.01);  // Monte Carlo standard error <= 0.0025
    EXPECT_GT(exact, 0.02);               // a case with something to estimate
    EXPECT_LT(exact, 0.5);
}

TEST(TwoSampleTests, SignFlipTestFindsASharedShiftTheUnpairedTestMisses) {
    // b = a + 0.05 for every member, spread 1 between members: the exact sign-flip p is 2 / 2^16.
    SplitMix64 rng(41);
    std::vector<double> a, b;
    for (int i = 0; i < 16; ++i) {
        a.push_back(rng.normal());
        b.push_back(a.back() + 0.05);
    }
    EXPECT_GT(energyPermutationTest(scalars(a), scalars(b), 999, 1).p_value, 0.5);
    EXPECT_LE(pairedSignFlipTest(a, b, 999, 1).p_value, 2.0 / 1000.0);
    // All differences zero: nothing to tell, p = 1.
    EXPECT_DOUBLE_EQ(pairedSignFlipTest(a, a, 99, 1).p_value, 1.0);
}

TEST(TwoSampleTests, SignFlipTestHoldsItsLevelUnderTheNull) {
    SplitMix64 rng(77);
    int rejected = 0;
    for (int t = 0; t < 200; ++t) {
        std::vector<double> a, b;
        for (int i = 0; i < 12; ++i) {
            a.push_back(rng.normal());
            b.push_back(a.back() + rng.normal());  // symmetric differences
        }
        if (pairedSignFlipTest(a, b, 99, static_cast<std::uint64_t>(t)).p_value < 0.05) ++rejected;
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
