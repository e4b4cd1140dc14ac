// SPDX-License-Identifier: MIT
// `vroc ensemble`: the comparison that survives chaos (metric M20, docs/harness.md). N copies of
// a scene, each with its virtual bodies' initial states perturbed by seeded Gaussian noise, run on
// every backend (member m gets the same perturbation on every backend); then, per observable that
// stays meaningful in chaos (rest positions, first impact times, impacts, final energy, rest time),
// an energy-distance permutation test between each pair of backends' ensembles, Holm-adjusted
// over the family, says whether the backends are statistically distinguishable.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "vroc/core/scene.h"
#include "vroc/harness/backend_selection.h"
#include "vroc/harness/metrics_document.h"
#include "vroc/harness/run_pool.h"

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

/// Runs every (backend, member) over `pool` and returns the metrics document.
Json runEnsemble(const Scene& scene, const std::vector<SelectedBackend>& backends, const EnsembleOptions& options, RunPool& pool);

/// One line per backend pair: which observables distinguish them and which do not.
std::string ensembleVerdictText(const Json& doc);

}  // namespace vroc::harness
