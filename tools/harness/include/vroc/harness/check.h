// SPDX-License-Identifier: MIT
// `vroc check`: runs the analytic suite on each backend, prints the check x backend table and
// writes metrics.json and report.html. Exit code 1 when a check required for "native" fails on
// the backend named native.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "vroc/harness/backend_selection.h"
#include "vroc/harness/metrics_document.h"
#include "vroc/harness/run_pool.h"

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

/// Runs the suite, one pool job per (scenario, backend); the document's results.checks lists every
/// metric with per-backend {measured, pass} and results.required_failures_native counts the
/// failures that set exit 1.
Json runCheckSuite(const std::vector<SelectedBackend>& backends, const CheckOptions& options, RunPool& pool);

/// The same, one run after another in this process, writing nothing.
Json runCheckSuite(const std::vector<SelectedBackend>& backends, const CheckOptions& options);

/// What the suite's runs depend on, for RunPool (--resume).
Json checkPlan(const std::vector<SelectedBackend>& backends, const CheckOptions& options);

/// The plain-text table printed on stdout.
std::string checkTableText(const Json& doc);

/// Exit code for a finished suite: 1 if a required-for-native check failed on native, else 0.
int checkExitCode(const Json& doc);

}  // namespace vroc::harness
