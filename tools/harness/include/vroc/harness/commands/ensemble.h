// SPDX-License-Identifier: MIT
// `vroc ensemble`: the comparison that survives chaos (metric M20, docs/harness.md). N copies of
// a scene, each with its virtual bodies' initial states perturbed by seeded Gaussian noise, run on
// every backend (member m gets the same perturbation on every backend); then, per observable that
// stays meaningful in chaos (rest positions, first impact times, impacts, final energy, rest time),
// an energy-distance permutation test between each pair of backends' ensembles (and for scalars a
// paired sign-flip test over the members that share a start), Holm-adjusted over the family, and
// an effect size above the pair's resolution floor say whether the backends are distinguishable;
// members dropped from a test are named with why, and an event no member reaches is "not reached".
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "vroc/core/scene.h"
#include "vroc/harness/documents/metrics_document.h"
#include "vroc/harness/pool/run_pool.h"
#include "vroc/harness/runs/backend_selection.h"
#include "vroc/harness/statistics/two_sample_tests.h"

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

/// How finely a backend can tell an observable: what no difference smaller than counts.
enum class ObservableTiming {
    none,     ///< not a time: no resolution floor
    event,    ///< time of a collision event: reported at the end of the internal step that found it
              ///< (docs/events.md), so known to one internal step
    sampled,  ///< read from the recorded frames (rest time): known to one recorded frame
};

/// An observable that stays meaningful in chaos.
struct EnsembleObservable {
    std::string id;       ///< "rest_positions", "first_impact_time:<body>", ...
    std::string title;
    std::string units;
    ObservableTiming timing = ObservableTiming::none;  ///< event and sampled times can be "not reached"
};

/// One member run on one backend.
struct EnsembleMember {
    int member = 0;
    bool finite = true;
    bool valid = true;           ///< runValidity (run_validity.h): a not valid run is dropped from every test
    std::string invalid_reason;  ///< empty when valid
    std::map<std::string, std::vector<double>> observables;   ///< by id; NaN where not finite
    /// Ids of the time observables whose event never happened in this run; their value is the end of the run.
    std::vector<std::string> not_reached;
    /// [s] how finely this run's event times are known: its mean internal step (simulated time /
    /// internal steps), at most frame_dt; frame_dt when the backend does not count its steps.
    double event_time_resolution = 0;
    std::vector<double> t;                ///< [s] sampled frames (about series_points)
    std::vector<double> kinetic_energy;   ///< [J] at those frames
    std::vector<double> mean_height;      ///< [m] mean z of the virtual bodies' centres of mass
    std::string state_hash;               ///< of the last frame
    double wall_s = 0;                    ///< [s] of its steps
};

/// A member left out of one observable's tests, and why.
struct DroppedMember {
    int member = 0;
    std::string reason;  ///< "not valid: ..." (run_validity.h) or "value not finite"
};

/// What a test between two backends' ensembles of one observable concluded.
enum class EnsembleVerdict {
    distinguishable,      ///< Holm-adjusted p < alpha and the effect exceeds the resolution floor
    not_distinguishable,  ///< Holm-adjusted p >= alpha
    within_resolution,    ///< p < alpha, but the effect is no larger than the coarser backend's resolution
    not_reached,          ///< no member of one backend (or either) reached the event: nothing to compare
    too_few_members,      ///< fewer than 2 usable members on one side
};
const char* verdictName(EnsembleVerdict v);  ///< "distinguishable", "not distinguishable", ...

/// How large a distinguishable difference is, for the digest's colours.
enum class EffectClass { none, small, medium, large, not_applicable };
const char* effectClassName(EffectClass c);  ///< "none", "small", "medium", "large", "n/a"

/// One two-sample test: observable x backend pair.
struct EnsembleTest {
    std::string observable;
    std::string a, b;                          ///< backend names
    std::size_t members_a = 0, members_b = 0;  ///< usable members (valid run, finite value)
    std::size_t reached_a = 0, reached_b = 0;  ///< of those, members whose event happened (= members for non-times)
    std::vector<DroppedMember> dropped_a, dropped_b;
    PermutationTest test;                 ///< unbiased energy distance [units] and its permutation p-value
    PairedTest paired;                    ///< scalars: sign-flip test over members usable on both (pairs = 0: none)
    double wasserstein1 = NAN;            ///< [units] scalar observables only
    double effect = NAN;                  ///< [units] marginalWasserstein1 (scalars: Wasserstein-1)
    double resolution_a = 0, resolution_b = 0;  ///< [units] how finely each backend tells it (0: exact)
    double floor = 0;                           ///< [units] max(resolution_a, resolution_b): no smaller effect counts
    double spread = NAN;  ///< [units] pooled spread: sqrt((s_a^2 + s_b^2) / 2), s = std or RMS distance to the mean
    double standardized_effect = NAN;  ///< effect / max(floor, spread); inf when both are 0 and effect > 0
    double p_holm_unpaired = NAN;      ///< the energy test's p, Holm-adjusted over the whole family
    double p_holm_paired = NAN;        ///< the paired test's p, Holm-adjusted (NaN: no paired test)
    double p_holm = NAN;               ///< the smaller of the two: the verdict's
    bool distinguishable = false;      ///< verdict == distinguishable
    EnsembleVerdict verdict = EnsembleVerdict::too_few_members;
    EffectClass effect_class = EffectClass::not_applicable;
    std::vector<std::string> not_reached_by;  ///< backends none of whose members reached the event
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

/// The members' values of one observable, one Sample each (a not valid run or a missing or
/// non-finite value drops that member).
std::vector<Sample> ensembleSamples(const std::vector<EnsembleMember>& members, const std::string& id);

/// The members `ensembleSamples` leaves out of observable `id`, each with why.
std::vector<DroppedMember> droppedMembers(const std::vector<EnsembleMember>& members, const std::string& id);

/// What one backend's members give for one observable: the usable values, their member numbers,
/// how many reached the event, the dropped members and the backend's resolution [units].
struct EnsembleSide {
    std::string backend;
    std::vector<Sample> values;
    std::vector<int> members;  ///< member number of each value
    std::size_t reached = 0;
    std::vector<DroppedMember> dropped;
    double resolution = 0;  ///< [units]
};

EnsembleSide ensembleSide(const std::string& backend, const std::vector<EnsembleMember>& members,
                          const EnsembleObservable& ob, double sampled_resolution);

/// How many hypotheses a test of these two sides adds to the family: 0 (too few members, not
/// reached), 1 (the energy test) or 2 (and the paired test: scalars with at least 2 pairs).
std::size_t ensembleHypotheses(const EnsembleObservable& ob, const EnsembleSide& a, const EnsembleSide& b);

/// Tests one observable between two sides with `permutations` per test; p_holm and the verdict
/// are left for concludeEnsembleTests (they depend on the whole family).
EnsembleTest ensembleTest(const EnsembleObservable& ob, const EnsembleSide& a, const EnsembleSide& b, int permutations,
                          std::uint64_t seed);

/// Holm-adjusts every test's p-values over the family (the energy tests and the paired tests of
/// every tested pair) and sets each verdict: distinguishable when p_holm < alpha and the effect
/// exceeds the floor.
void concludeEnsembleTests(std::vector<EnsembleTest>& tests, double alpha);

}  // namespace vroc::harness
