// SPDX-License-Identifier: MIT
// Every backend the conformance suite holds to the contract: one line each.
#pragma once

#include <cstdlib>
#include <string>
#include <vector>

#include "vroc/bullet/bullet_backend.h"
#include "vroc/core/backend_registry.h"
#include "vroc/dart/dart_backend.h"
#include "vroc/mujoco/mujoco_backend.h"
#include "vroc/native/native_backend.h"
#include "vroc/ode/ode_backend.h"

namespace vroc::conformance {

struct ConformanceBackend {
    std::string name;        ///< as registered
    void (*register_fn)();   ///< adds it to BackendRegistry::global() (idempotent here)
    /// The shipped-scenes check and the pinned hashes include scenes/stress/. False for a backend
    /// whose piles cost minutes there (DART: a dense LCP per pile); the `long` test
    /// ConformanceStress.* runs them with VROC_CONFORMANCE_STRESS=1.
    bool stress_scenes = true;
};

inline const std::vector<ConformanceBackend>& conformanceBackends() {
    static const std::vector<ConformanceBackend> list{
        {"native", &native::registerBackend},
        {"bullet", &bullet::registerBackend},
        {"ode", &ode::registerBackend},
        {"mujoco", &mujoco::registerBackend},
        {"dart", &dart::registerBackend, false},
    };
    return list;
}

/// Whether the default suite runs `name`'s stress scenes (always with VROC_CONFORMANCE_STRESS=1).
inline bool runsStressScenes(const std::string& name) {
    const char* all = std::getenv("VROC_CONFORMANCE_STRESS");
    if (all && std::string(all) == "1") return true;
    for (const ConformanceBackend& b : conformanceBackends())
        if (b.name == name) return b.stress_scenes;
    return true;
}

/// Registers every backend above (once) and returns `name`'s registration.
inline const BackendInfo& registeredBackend(const std::string& name) {
    for (const ConformanceBackend& b : conformanceBackends())
        if (!BackendRegistry::global().find(b.name)) b.register_fn();
    return BackendRegistry::global().require(name);
}

}  // namespace vroc::conformance
