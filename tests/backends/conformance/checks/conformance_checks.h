// SPDX-License-Identifier: MIT
// Every check of the conformance suite, by name: the real backends must pass each one
// (backend_conformance_test.cpp), and each broken backend must fail the ones its entry in
// broken_backends/broken_backends.h names and pass the others (broken_backends_test.cpp).
#pragma once

#include <string>
#include <vector>

#include "checks/capability_notes_check.h"
#include "checks/impulse_check.h"
#include "checks/landing_check.h"
#include "checks/shape_support_check.h"
#include "checks/shipped_scenes_check.h"
#include "checks/worker_count_check.h"
#include "conformance_backends.h"

namespace vroc::conformance {

struct ConformanceCheck {
    std::string name;                                  ///< as broken_backends.h names it
    CheckResult (*run)(const BackendInfo&) = nullptr;  ///< at its default options
};

inline const std::vector<ConformanceCheck>& conformanceChecks() {
    static const std::vector<ConformanceCheck> list{
        {"shipped_scenes",
         [](const BackendInfo& b) {
             ShippedScenesCheckOptions options;
             options.stress_scenes = runsStressScenes(b.name);
             return checkShippedScenes(b, options);
         }},
        {"landing", [](const BackendInfo& b) { return checkLanding(b); }},
        {"worker_count", [](const BackendInfo& b) { return checkWorkerCountDeterminism(b); }},
        {"impulse", &checkImpulse},
        {"shape_support", &checkShapeSupport},
        {"capability_notes", &checkCapabilityNotes},
    };
    return list;
}

}  // namespace vroc::conformance
