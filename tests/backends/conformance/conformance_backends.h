// SPDX-License-Identifier: MIT
// Every backend the conformance suite holds to the contract: one line each.
#pragma once

#include <string>
#include <vector>

#include "vroc/bullet/bullet_backend.h"
#include "vroc/core/backend_registry.h"
#include "vroc/mujoco/mujoco_backend.h"
#include "vroc/native/native_backend.h"
#include "vroc/ode/ode_backend.h"

namespace vroc::conformance {

struct ConformanceBackend {
    std::string name;        ///< as registered
    void (*register_fn)();   ///< adds it to BackendRegistry::global() (idempotent here)
};

inline const std::vector<ConformanceBackend>& conformanceBackends() {
    static const std::vector<ConformanceBackend> list{
        {"native", &native::registerBackend},
        {"bullet", &bullet::registerBackend},
        {"ode", &ode::registerBackend},
        {"mujoco", &mujoco::registerBackend},
    };
    return list;
}

/// Registers every backend above (once) and returns `name`'s registration.
inline const BackendInfo& registeredBackend(const std::string& name) {
    for (const ConformanceBackend& b : conformanceBackends())
        if (!BackendRegistry::global().find(b.name)) b.register_fn();
    return BackendRegistry::global().require(name);
}

}  // namespace vroc::conformance
