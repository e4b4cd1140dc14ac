// SPDX-License-Identifier: MIT
// `vroc ensemble`: the comparison that survives chaos (metric M20, docs/harness.md). N copies of
// a scene, each with its virtual bodies' initial states perturbed by seeded Gaussian noise, run on
// every backend (member m gets the same perturbation on every backend); then, per observable that
// stays meaningful in chaos (rest positions, first impact times, impacts, final energy, rest time),
// an energy-distance permutation test between each pair of backends' ensembles, Holm-adjusted
// over the family, says whether the backends are statistically distinguishable.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "vroc/core/scene.h"
#include "vroc/harness/backend_selection.h"
#include "vroc/harness/metrics_document.h"
#include "vroc/harness/run_pool.h"
#include "vroc/harness/two_sample_tests.h"

namespace vroc::harness {

/// Standard deviations of the Gaussian noise added to each virtual body's initial state.
struct Perturbation {
    double position = 1e-6;      ///< [m] per component
    double velocity = 0;         ///< [m/s] per component
    double orientation = 0;      ///< [rad] per component of a small rotation vector
    double angular_velocity = 0; ///< [rad/s] per component
};

/// "positions=1e-6,velocities=1e-4,orientations=0,angular=0" (any subset); throws InputError.
Perturbation parsePerturbation(const std::string& text);

struct EnsembleOptions {
    int members = 32;                 ///< per backend
    Perturbation perturb;
    double duration = 4.0;            ///< [s] of each member
    double frame_dt = 1.0 / 60.0;     ///< [s]
    std::uint64_t seed = 1;           ///< perturbations and permutations
    int permutations = 0;             ///< per test; 0: max(999, 2 x tests / alpha), so every test can pass Holm
    double alpha = 0.05;              ///< family-wise error rate (Holm)
    int series_points = 200;          ///< samples of the spread-over-time charts
    std::string source;               ///< the scene as given
    std::string command_line;
};

/// The perturbed initial states of member `member` (indexed like Scene::bodies; real bodies untouched).
std::vector<BodyState> ensembleMemberStates(const Scene& scene, const Perturbation& p, std::uint64_t seed, int member);

/// What the members' runs depend on, for RunPool (--resume).
Json ensemblePlan(const Scene& scene, const std::vector<SelectedBackend>& backends, const EnsembleOptions& options);

/// An observable that stays meaningful in chaos.
struct EnsembleObservable {
    std::string id;       ///< "rest_positions", "first_impact_time:<body>", ...
    std::string title;
    std::string units;
};

/// One member run on one backend.
struct EnsembleMember {
    int member = 0;
    bool finite = true;
    std::map<std::string, std::vector<double>> observables;   ///< by id; NaN where not finite
    std::vector<double> t;                ///< [s] sampled frames (about series_points)
    std::vector<double> kinetic_energy;   ///< [J] at those frames
    std::vector<double> mean_height;      ///< [m] mean z of the virtual bodies' centres of mass
    std::string state_hash;               ///< of the last frame
    double wall_s = 0;                    ///< [s] of its steps
};

/// One two-sample test: observable x backend pair.
struct EnsembleTest {
    std::string observable;
    std::string a, b;                     ///< backend names
    std::size_t members_a = 0, members_b = 0;   ///< with a finite value
    PermutationTest test;                 ///< energy distance [units] and permutation p-value
    double wasserstein1 = NAN;            ///< [units] scalar observables only
    double p_holm = NAN;                  ///< Holm-adjusted over the whole family
    bool distinguishable = false;         ///< p_holm < alpha
};

struct EnsembleResult {
    Scene scene;
    EnsembleOptions options;
    std::vector<SelectedBackend> backends;   ///< those that can represent the scene
    Json support;                            ///< per requested backend, as representableBackends gives it
    std::vector<EnsembleObservable> observables;
    std::vector<std::vector<EnsembleMember>> members;   ///< [backend][member]
    int permutations = 0;                    ///< per test
    std::vector<EnsembleTest> tests;
    PoolExecution execution;
};

/// Runs every (backend, member) over `pool` and tests every observable between every pair.
EnsembleResult runEnsemble(const Scene& scene, const std::vector<SelectedBackend>& backends, const EnsembleOptions& options,
                           RunPool& pool);

/// The members' values of one observable, one Sample each (a missing or non-finite value drops
/// that member).
std::vector<Sample> ensembleSamples(const std::vector<EnsembleMember>& members, const std::string& id);

}  // namespace vroc::harness
