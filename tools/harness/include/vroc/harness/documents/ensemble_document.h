// SPDX-License-Identifier: MIT
// Writers for a finished `vroc ensemble`, from the typed result alone: the metrics document
// (docs/metrics-schema.md) and the verdict lines printed on stdout.
#pragma once

#include <string>

#include "vroc/harness/commands/ensemble.h"
#include "vroc/harness/documents/metrics_document.h"

namespace vroc::harness {

/// Tests, verdicts per pair, members per backend (without their series) and the members dropped
/// from each observable; the digest (observables x backend pairs, each cell coloured by its
/// effect), the test table, the dropped members' table (when any) and the summary table; the
/// spread-over-time charts.
Json ensembleDocument(const EnsembleResult& result);

/// One line per backend pair: which observables distinguish them, which do not, which only within
/// the resolution, which are not reached; then which members were dropped.
std::string ensembleVerdictText(const EnsembleResult& result);

/// A member as metrics.json keeps it, and with `with_series` as it travels through the pool
/// (member, finite, valid, invalid_reason, observables, not_reached, event_time_resolution_s,
/// state_hash, wall_s; series t_s, kinetic_energy_J, mean_height_m).
Json ensembleMemberJson(const EnsembleMember& member, bool with_series);

}  // namespace vroc::harness
