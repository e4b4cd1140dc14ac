// SPDX-License-Identifier: MIT
// Writers for a finished `vroc check`: its metrics document (docs/metrics-schema.md; the report is
// rendered from it) and the plain-text table printed on stdout. Both read only the typed result.
#pragma once

#include <string>

#include "vroc/harness/commands/check.h"
#include "vroc/harness/documents/metrics_document.h"

namespace vroc::harness {

/// metrics.json for the suite: results.checks lists every metric with per-backend
/// {measured, pass, support}, results.required_failures_native counts the failures that set exit 1;
/// the checks x backends table and the error / tolerance chart.
Json checkDocument(const CheckSuiteResult& result, const std::string& command_line);

/// The check x backend table: measured value and pass / FAIL / info per backend ("n/s": not
/// supported, "~": approximated), then one line per backend and reason for those marks.
std::string checkTableText(const CheckSuiteResult& result);

}  // namespace vroc::harness
