// SPDX-License-Identifier: MIT
// Two-sample statistics for ensembles (metric M20 of docs/harness.md): are two backends' ensembles
// of one observable drawn from the same distribution? Energy distance (Székely and Rizzo) works in
// any dimension; Wasserstein-1 is reported for scalars in the observable's own units; a permutation
// test turns the energy distance into a p-value; a sign-flip test uses the pairing of members run
// from the same start on two backends; Holm's method adjusts p-values over many tests.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace vroc::harness {

using Sample = std::vector<double>;   ///< one observation (length 1 for a scalar observable)

/// 2 E|X-Y| - E|X-X'| - E|Y-Y'| with Euclidean distances, as the unbiased U-statistic: the
/// within-sample means run over i != j (divide by n(n-1), not n^2), so its mean over draws of two
/// samples from one distribution is 0 (it can be negative); the V-statistic's n^2 adds
/// E|X-X'|/n + E|Y-Y'|/m, 7 % of the standard deviation of a normal at n = m = 32 (Szekely and
/// Rizzo 2013, "Energy statistics", J. Stat. Plan. Inference 143). Each sample needs at least 2
/// observations.
/// Units: those of the observable.
double energyDistance(const std::vector<Sample>& x, const std::vector<Sample>& y);

/// Wasserstein-1 distance between two empirical distributions of scalars: the area between their
/// CDFs. Units: those of the observable.
double wasserstein1(std::vector<double> x, std::vector<double> y);

/// An effect size in the observable's units for samples of any dimension: the Wasserstein-1
/// distance of each coordinate's marginals, combined as a Euclidean norm. For scalars it is
/// wasserstein1; for vectors a lower bound of the joint Wasserstein-1 (each marginal's is at most
/// the joint one, and the norm of the mean is at most the mean of the norm), equal to |shift| when
/// one ensemble is the other translated.
double marginalWasserstein1(const std::vector<Sample>& x, const std::vector<Sample>& y);

struct PermutationTest {
    double statistic = 0;   ///< energy distance of the observed split
    double p_value = 1;     ///< (1 + #{permuted >= observed}) / (1 + permutations)
    int permutations = 0;
};

/// Permutation test of equal distributions with the energy distance as statistic. The shuffles come
/// from a seeded generator, so the p-value is reproducible.
PermutationTest energyPermutationTest(const std::vector<Sample>& x, const std::vector<Sample>& y, int permutations,
                                      std::uint64_t seed);

/// Fisher's sign-flip randomisation test on paired scalars: member k of `a` and of `b` started from
/// the same state, so under "the two backends are exchangeable for each start" each difference
/// a[k] - b[k] is symmetric about 0 and flipping its sign leaves the distribution unchanged.
/// Statistic |mean difference|, two-sided. Chosen over Wilcoxon's signed-rank test because
/// ensembles have many zero and tied differences (counts, frame-quantised times) that need no
/// special rule here, and the statistic is in the observable's units. Pairing removes the
/// between-member spread that an unpaired test must see through: a shift much smaller than the
/// spread, shared by every member, is found by this test and missed by the energy test.
struct PairedTest {
    std::size_t pairs = 0;
    double mean_difference = 0;  ///< mean of a[k] - b[k] [units]
    double p_value = 1;          ///< (1 + #{flipped |mean| >= observed}) / (1 + permutations)
    int permutations = 0;
};

/// a[k] is paired with b[k] (same size, >= 1); seeded like energyPermutationTest.
PairedTest pairedSignFlipTest(const std::vector<double>& a, const std::vector<double>& b, int permutations,
                              std::uint64_t seed);

/// Holm–Bonferroni adjusted p-values (same order as the input): controls the chance of any false
/// "distinguishable" over the whole family of tests.
std::vector<double> holmAdjusted(const std::vector<double>& p);

/// SplitMix64: the harness's seeded generator (ensemble perturbations, permutations).
class SplitMix64 {
public:
    explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
    std::uint64_t next();
    double uniform();    ///< [0, 1)
    double normal();     ///< standard normal (Box–Muller; one value per call)

private:
    std::uint64_t state_;
};

}  // namespace vroc::harness
