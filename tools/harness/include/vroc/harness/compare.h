// SPDX-License-Identifier: MIT
// `vroc compare`: one scene on several backends, with the numbers that survive chaos
// (docs/harness.md). Writes metrics.json, per-backend CSVs and report.html.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "vroc/core/scene.h"
#include "vroc/harness/backend_selection.h"
#include "vroc/harness/metrics_document.h"
#include "vroc/harness/run_pool.h"

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

/// Runs everything over `pool` (per backend: main, rerun and twin; then the re-anchored windows)
/// and returns the metrics document; writes only the CSV files (rank 0, when csv_dir is set).
Json compareScene(const Scene& scene, const std::vector<SelectedBackend>& backends, const CompareOptions& options,
                  const std::filesystem::path& csv_dir, RunPool& pool);

/// The same, one run after another in this process.
Json compareScene(const Scene& scene, const std::vector<SelectedBackend>& backends, const CompareOptions& options,
                  const std::filesystem::path& csv_dir);

/// What the comparison's runs depend on, for RunPool (--resume).
Json comparePlan(const Scene& scene, const std::vector<SelectedBackend>& backends, const CompareOptions& options);

}  // namespace vroc::harness
