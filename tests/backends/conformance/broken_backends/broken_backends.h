// SPDX-License-Identifier: MIT
// The broken backends (and the one control), each with the checks of checks/conformance_checks.h
// that must reject it. Every other check must pass it: a broken backend breaks one thing, so a
// check it fails is a check that can fail for that reason (docs/backend-contract.md, "The
// conformance suite").
#pragma once

#include <set>
#include <string>
#include <vector>

#include "broken_backends/accepts_unsupported_backend.h"
#include "broken_backends/compound_refusing_backend.h"
#include "broken_backends/frozen_backend.h"
#include "broken_backends/no_contacts_backend.h"
#include "broken_backends/thread_dependent_hash_backend.h"
#include "broken_backends/unexplained_approximation_backend.h"
#include "broken_backends/wrong_capability_backend.h"
#include "broken_backends/wrong_frame_impulse_backend.h"

namespace vroc::conformance {

struct BrokenBackend {
    BackendInfo (*info)() = nullptr;    ///< builds its BackendInfo (wrapping native)
    std::set<std::string> rejected_by;  ///< names in conformanceChecks(); empty: the control
};

inline const std::vector<BrokenBackend>& brokenBackends() {
    static const std::vector<BrokenBackend> list{
        {&frozenBackend, {"shipped_scenes", "landing"}},
        {&noContactsBackend, {"landing"}},
        {&wrongFrameImpulseBackend, {"impulse"}},
        {&threadDependentHashBackend, {"worker_count"}},
        {&wrongCapabilityBackend, {"landing"}},
        {&acceptsUnsupportedBackend, {"shape_support", "shipped_scenes"}},
        {&unexplainedApproximationBackend, {"capability_notes"}},
        {&compoundRefusingBackend, {}},
    };
    return list;
}

}  // namespace vroc::conformance
