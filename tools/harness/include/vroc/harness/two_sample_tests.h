// SPDX-License-Identifier: MIT
// Two-sample statistics for ensembles (metric M20 of docs/harness.md): are two backends' ensembles
// of one observable drawn from the same distribution? Energy distance (Székely and Rizzo) works in
// any dimension; Wasserstein-1 is reported for scalars in the observable's own units; a permutation
// test turns the energy distance into a p-value; Holm's method adjusts p-values over many tests.
#pragma once

#include <cstdint>
#include <vector>

namespace vroc::harness {

using Sample = std::vector<double>;   ///< one observation (length 1 for a scalar observable)

/// 2 E|X-Y| - E|X-X'| - E|Y-Y'| with Euclidean distances, V-statistic form (>= 0; 0 iff the two
/// empirical distributions are equal). Units: those of the observable.
double energyDistance(const std::vector<Sample>& x, const std::vector<Sample>& y);

/// Wasserstein-1 distance between two empirical distributions of scalars: the area between their
/// CDFs. Units: those of the observable.
double wasserstein1(std::vector<double> x, std::vector<double> y);

struct PermutationTest {
    double statistic = 0;   ///< energy distance of the observed split
    double p_value = 1;     ///< (1 + #{permuted >= observed}) / (1 + permutations)
    int permutations = 0;
};

/// Permutation test of equal distributions with the energy distance as statistic. The shuffles come
/// from a seeded generator, so the p-value is reproducible.
PermutationTest energyPermutationTest(const std::vector<Sample>& x, const std::vector<Sample>& y, int permutations,
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
