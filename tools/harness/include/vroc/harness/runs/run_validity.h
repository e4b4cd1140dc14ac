// SPDX-License-Identifier: MIT
// Whether a run is the engine's physics. A run in which the engine dropped contacts because a
// buffer was full (the shared warning `contacts_dropped`), or reported a state that was not
// finite, is not valid: every table, chart and consensus marks it so, with the reason, and no
// verdict counts it as that engine's behaviour (issue 23, "a reference never fails because of the
// harness").
#pragma once

#include <string>

#include "vroc/core/backend.h"

namespace vroc::harness {

struct RunTrace;

struct RunValidity {
    bool valid = true;
    std::string reason;  ///< empty when valid; else what made it not valid, for a table cell
};

/// From a run's counted warnings and its finiteness.
RunValidity runValidity(const WarningCounts& warnings, bool finite);
RunValidity runValidity(const RunTrace& trace);

/// "not valid: <reason>" for a table cell, or "" when valid.
std::string invalidLabel(const RunValidity& v);

}  // namespace vroc::harness
