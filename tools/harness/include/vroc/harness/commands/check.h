// SPDX-License-Identifier: MIT
// `vroc check`: runs the analytic suite on each backend and returns a CheckSuiteResult; the
// metrics document (check_document.h) and the printed table are written from it. Exit code 1
// when a check required for "native" fails on the backend named native.
#pragma once

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "vroc/harness/commands/check_suite.h"
#include "vroc/harness/documents/metrics_document.h"
#include "vroc/harness/pool/run_pool.h"
#include "vroc/harness/runs/backend_selection.h"
#include "vroc/harness/runs/run_validity.h"
#include "vroc/harness/runs/scene_support.h"

namespace vroc::harness {

struct CheckOptions {
    bool long_set = false;
    bool progress = true;
    std::string command_line;
    std::vector<std::string> only;   ///< scenario ids to run (empty: all)
    /// Append the stress section (stressScenarios) after the analytic scenarios. Also turned on
    /// when `only` names a stress id.
    bool stress = false;
    std::filesystem::path scenes_dir = "scenes/stress";   ///< where the stress scenes are
};

/// One metric measured on one backend.
struct CheckCell {
    /// In the metric's units; NaN: not run, the run went non-finite, or the run does not record the
    /// quantity (a statistic the backend does not keep: reported as "—").
    double measured = NAN;
    std::optional<bool> pass;      ///< empty: reported, not judged (or not run)
    SceneSupport support;          ///< Unsupported: the scenario was not run on this backend
    /// Not valid: the engine dropped contacts in this run (a full buffer); the cell is reported,
    /// never judged. A run that went non-finite stays valid, and fails: that is the backend's.
    RunValidity validity;
};

/// One metric of the suite and its cell per backend (CheckSuiteResult::backends order).
struct CheckRow {
    std::string scenario;          ///< CheckScenario::id
    CheckMetric metric;            ///< its measure is not called again
    std::vector<CheckCell> cells;
};

struct CheckSuiteResult {
    std::vector<SelectedBackend> backends;
    bool long_set = false;
    bool stress = false;                       ///< the stress section ran (asked for, or implied by --only)
    std::filesystem::path scenes_dir;          ///< of the stress scenes, when stress
    std::size_t scenario_count = 0;
    std::vector<CheckRow> rows;                ///< every metric, in suite order
    std::vector<double> wall_time_s;           ///< [s] per backend: the sum of its runs' wall times
    int required_failures_native = 0;          ///< required metrics failed on the backend named "native"
    PoolExecution execution;

    /// 1 if a required-for-native check failed on native, else 0.
    int exitCode() const { return required_failures_native > 0 ? 1 : 0; }
};

/// The verdict behind exitCode(): how many cells of the backend named "native" fail a metric
/// required for native (cells are in `backends` order).
int requiredFailuresNative(const std::vector<SelectedBackend>& backends, const std::vector<CheckRow>& rows);

/// Runs the suite, one pool job per (scenario, backend).
CheckSuiteResult runCheckSuite(const std::vector<SelectedBackend>& backends, const CheckOptions& options, RunPool& pool);

/// The same, one run after another in this process, writing nothing.
CheckSuiteResult runCheckSuite(const std::vector<SelectedBackend>& backends, const CheckOptions& options);

/// What the suite's runs depend on, for RunPool (--resume).
Json checkPlan(const std::vector<SelectedBackend>& backends, const CheckOptions& options);

}  // namespace vroc::harness
