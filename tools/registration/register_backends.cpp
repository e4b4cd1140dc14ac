// SPDX-License-Identifier: MIT
#include "vroc/registration/register_backends.h"

#include "vroc/bullet/bullet_backend.h"
#include "vroc/core/backend_registry.h"
#include "vroc/dart/dart_backend.h"
#include "vroc/mujoco/mujoco_backend.h"
#include "vroc/native/native_backend.h"
#include "vroc/ode/ode_backend.h"

namespace vroc::registration {

void registerBackends() {
    const BackendRegistry& registry = BackendRegistry::global();
    if (!registry.find("bullet")) vroc::bullet::registerBackend();
    if (!registry.find("dart")) vroc::dart::registerBackend();
    if (!registry.find("mujoco")) vroc::mujoco::registerBackend();
    if (!registry.find("native")) vroc::native::registerBackend();
    if (!registry.find("ode")) vroc::ode::registerBackend();
}

}  // namespace vroc::registration
