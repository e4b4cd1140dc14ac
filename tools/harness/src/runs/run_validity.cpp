// SPDX-License-Identifier: MIT
#include "vroc/harness/runs/run_validity.h"

#include "vroc/core/backend_vocabulary.h"
#include "vroc/harness/runs/run_trace.h"

namespace vroc::harness {

RunValidity runValidity(const WarningCounts& warnings, bool finite) {
    RunValidity v;
    const auto dropped = warnings.find(vocabulary::kContactsDropped);
    if (dropped != warnings.end() && dropped->second > 0) {
        v.valid = false;
        v.reason = "the engine dropped contacts " + std::to_string(dropped->second) +
                   " times (a buffer was full: " + vocabulary::kContactsDropped + ")";
    }
    if (!finite) {
        v.valid = false;
        v.reason += std::string(v.reason.empty() ? "" : "; ") + "a reported state was not finite";
    }
    return v;
}

RunValidity runValidity(const RunTrace& trace) { return runValidity(trace.warnings, trace.finite); }

std::string invalidLabel(const RunValidity& v) { return v.valid ? std::string() : "not valid: " + v.reason; }

}  // namespace vroc::harness
