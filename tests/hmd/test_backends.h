// SPDX-License-Identifier: MIT
// Registers the Bullet and native backends once per test program.
#pragma once

#include "vroc/bullet/bullet_backend.h"
#include "vroc/core/backend_registry.h"
#include "vroc/native/native_backend.h"

namespace vroc::test {

inline void registerBackendsOnce() {
    static const bool done = [] {
        if (!BackendRegistry::global().find("bullet")) bullet::registerBackend();
        if (!BackendRegistry::global().find("native")) native::registerBackend();
        return true;
    }();
    (void)done;
}

}  // namespace vroc::test
