// SPDX-License-Identifier: MIT
// `vroc compare`: one scene on several backends, with the numbers that survive chaos
// (docs/harness.md). Returns a CompareResult; metrics.json and report.html are written from it
// (compare_document.h), the per-backend CSVs as the runs come in.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "vroc/core/scene.h"
#include "vroc/harness/documents/metrics_document.h"
#include "vroc/harness/metrics/divergence.h"
#include "vroc/harness/pool/run_pool.h"
#include "vroc/harness/runs/backend_selection.h"
#include "vroc/harness/runs/run_trace.h"
#include "vroc/harness/runs/run_validity.h"
#include "vroc/harness/statistics/consensus.h"
#include "vroc/harness/statistics/timing_stats.h"

namespace vroc::harness {

struct CompareOptions {
    double duration = 5.0;            ///< [s] simulated
    std::optional<double> frame_dt;   ///< [s] default: the scene's frame_dt
    int windows = 10;                 ///< K re-anchored windows
    double window = 0.25;             ///< [s] Δ, length of each window
    double twin_epsilon = 1e-9;       ///< [m] twin-run perturbation of every virtual body's position
    double horizon_delta = 1e-3;      ///< [m] δ of the predictability horizon
    bool write_csv = true;            ///< <out>/<backend>/{trajectory,events,step_times}.csv
    bool progress = true;             ///< lines on stderr
    std::string command_line;
};

/// The runs `vroc compare` makes on one backend.
struct BackendRuns {
    RunTrace main;                                     ///< from the scene's initial state
    RunTrace twin;                                     ///< every virtual body moved by ε along x
    std::vector<std::vector<BodyState>> window_ends;   ///< [anchor] state after one window
    std::vector<double> penetration;                   ///< [m] per frame of main (neutral query)
    std::string state_hash;                            ///< vroc::stateHash of main's final state
    bool deterministic = false;                        ///< a rerun ended with the same state hash (M22)
};

/// How far the conserved quantities of the main run moved over the run.
struct InvariantDrift {
    double energy_initial = 0;              ///< [J] mechanical energy of the virtual bodies at t0
    double energy_max_abs_change = 0;       ///< [J] max |E(t) - E(t0)|
    double energy_max_rel_change = NAN;     ///< [-] the same over |E(t0)|; NaN when E(t0) = 0
    double angular_momentum_max_change = 0; ///< [kg m^2/s] max |L(t) - L(t0)|
    double linear_momentum_max_change_beyond_gravity = 0;   ///< [kg m/s] max |p(t) - p(t0) - M g t|
};

struct BodyImpacts {
    std::string body;                       ///< virtual body name
    std::vector<double> times;              ///< [s] the first impacts (up to four)
    std::size_t count = 0;                  ///< impacts over the run
};

struct EventSummary {
    std::optional<double> first_contact;    ///< [s] first contact event
    std::size_t event_count = 0;
    std::optional<double> rest_time;        ///< [s] when every virtual body came to rest
    std::vector<BodyImpacts> per_body;      ///< virtual bodies, scene order
};

/// What one backend's runs measure.
struct CompareBackendSummary {
    RunValidity validity;                   ///< of the main and twin runs: not valid ones never vote
    TimingSummary timing;                   ///< of the main run's steps
    Histogram step_times_us;                ///< [µs] per-step wall time histogram (30 bins)
    double penetration_max = 0;             ///< [m] over frames
    double penetration_mean = 0;            ///< [m] over frames
    InvariantDrift invariants;
    EventSummary events;
    Divergence twin_spread;                 ///< main against twin: the backend's own noise floor
    std::optional<double> horizon;          ///< [s] predictability horizon t_δ of the twin spread
    std::optional<double> ftle;             ///< [1/s] finite-time Lyapunov exponent of the twin spread
    std::vector<double> window_position_error;   ///< [m] per anchor, against the reference backend
    std::vector<double> window_angle_error;      ///< [rad] per anchor
    double mean_window_position_error = NAN;     ///< [m]
    double mean_window_angle_error = NAN;        ///< [rad]
};

/// The reference backend (the first) against another, counted above both twin spreads.
struct ComparePair {
    std::size_t backend = 0;                ///< index of the other backend
    Divergence divergence;                  ///< frame by frame, reference main against its main
    Significance significance;
};

/// One row of the consensus table: which backends agree on an observable within their own twin
/// noise floors plus the observable's stated resolution (`floor`).
struct ConsensusRow {
    std::string observable;                 ///< with units
    double floor = 0;
    std::string floor_reason;
    std::vector<double> values;             ///< per backend; empty when only pairwise differences exist
    std::vector<double> noise;              ///< per backend: its twin difference
    ConsensusResult result;
};

struct CompareResult {
    Scene scene;
    std::vector<SelectedBackend> backends;  ///< those that can represent the scene; [0] is the reference
    Json support;                           ///< per requested backend, as representableBackends gives it
    double frame_dt = 0;                    ///< [s]
    double duration = 0;                    ///< [s]
    std::int64_t frames = 0;
    std::int64_t window_frames = 0;
    std::vector<std::size_t> anchors;       ///< frame indices where the windows start
    double twin_epsilon = 0;                ///< [m]
    double horizon_delta = 0;               ///< [m]
    std::vector<BackendRuns> runs;          ///< per backend
    std::vector<CompareBackendSummary> summaries;   ///< per backend
    std::vector<ComparePair> pairs;         ///< reference against each other backend
    std::vector<ConsensusRow> consensus;
    PoolExecution execution;
};

/// Runs everything over `pool` (per backend: main, rerun and twin; then the re-anchored windows);
/// writes only the CSV files (rank 0, when csv_dir is set).
CompareResult compareScene(const Scene& scene, const std::vector<SelectedBackend>& backends, const CompareOptions& options,
                           const std::filesystem::path& csv_dir, RunPool& pool);

/// The same, one run after another in this process.
CompareResult compareScene(const Scene& scene, const std::vector<SelectedBackend>& backends, const CompareOptions& options,
                           const std::filesystem::path& csv_dir);

/// What the comparison's runs depend on, for RunPool (--resume).
Json comparePlan(const Scene& scene, const std::vector<SelectedBackend>& backends, const CompareOptions& options);

}  // namespace vroc::harness
