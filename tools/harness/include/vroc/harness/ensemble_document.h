// SPDX-License-Identifier: MIT
// Writers for a finished `vroc ensemble`, from the typed result alone: the metrics document
// (docs/metrics-schema.md) and the verdict lines printed on stdout.
#pragma once

#include <string>

#include "vroc/harness/ensemble.h"
#include "vroc/harness/metrics_document.h"

namespace vroc::harness {

/// Tests, verdicts per pair, members per backend (without their series), the test and summary
/// tables and the spread-over-time charts.
Json ensembleDocument(const EnsembleResult& result);

/// One line per backend pair: which observables distinguish them and which do not.
std::string ensembleVerdictText(const EnsembleResult& result);

/// A member as metrics.json keeps it, and with `with_series` as it travels through the pool
/// (member, finite, observables, state_hash, wall_s; series t_s, kinetic_energy_J, mean_height_m).
Json ensembleMemberJson(const EnsembleMember& member, bool with_series);

}  // namespace vroc::harness
