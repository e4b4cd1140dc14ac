// SPDX-License-Identifier: MIT
// The metrics document of a finished `vroc compare` (docs/metrics-schema.md), written from the
// typed result alone: per-backend results, cross-backend pairs and the consensus; the consensus,
// summary and pair tables; trajectory, divergence, energy, penetration, window and step-time charts.
#pragma once

#include <string>

#include "vroc/harness/commands/compare.h"
#include "vroc/harness/documents/metrics_document.h"

namespace vroc::harness {

Json compareDocument(const CompareResult& result, const std::string& command_line);

}  // namespace vroc::harness
