// SPDX-License-Identifier: MIT
#include "register_backends.h"

#include "vroc/bullet/bullet_backend.h"
#include "vroc/mujoco/mujoco_backend.h"
#include "vroc/native/native_backend.h"
#include "vroc/ode/ode_backend.h"

namespace vroc::cli {

// The one place that names the backends: tools may know them, core never does.
void registerBackends() {
    vroc::bullet::registerBackend();
    vroc::mujoco::registerBackend();
    vroc::native::registerBackend();
    vroc::ode::registerBackend();
}

}  // namespace vroc::cli
