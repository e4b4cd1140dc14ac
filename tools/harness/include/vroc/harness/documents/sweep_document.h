// SPDX-License-Identifier: MIT
// The metrics document of a finished `vroc sweep` (docs/metrics-schema.md), written from the typed
// result alone: per curve its steps, convergence order, robustness limit and detail levels; the
// Pareto front; the tables and the speed-accuracy, convergence, closed-form and detail charts.
#pragma once

#include <string>

#include "vroc/harness/commands/sweep.h"
#include "vroc/harness/documents/metrics_document.h"

namespace vroc::harness {

Json sweepDocument(const SweepResult& result, const std::string& command_line);

/// One step as results.<curve>.steps[] holds it (also how a step run travels through the pool):
/// dt_s, robust, failure, state_hash, and for a measured step cost_wall_per_sim_s, window_error_m,
/// closed_form_error, step_p50_us.
Json sweepStepJson(const SweepStep& step);

/// One detail level as results.<curve>.detail.levels[] holds it.
Json sweepDetailJson(const SweepDetail& detail);

}  // namespace vroc::harness
