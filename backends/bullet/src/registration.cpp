// SPDX-License-Identifier: MIT
#include <LinearMath/btScalar.h>

#include <string>

#include "bullet_backend.h"
#include "vroc/bullet/bullet_backend.h"
#include "vroc/core/backend_registry.h"

static_assert(sizeof(btScalar) == 8, "the Bullet backend needs Bullet in double precision (bullet-float64)");

namespace vroc::bullet {
namespace {

std::unique_ptr<Backend> create(const Scene& scene, const Settings& settings) {
    return std::make_unique<BulletBackend>(scene, BulletConfig::from(settings));
}

std::string versionText() {
    return "Bullet " + std::to_string(BT_BULLET_VERSION / 100) + "." + std::to_string(BT_BULLET_VERSION % 100) +
           " (double)";
}

}  // namespace

void registerBackend() {
    if (BackendRegistry::global().find("bullet")) return;   // calling twice is harmless
    BackendInfo info;
    info.name = "bullet";
    info.description = "reference: Bullet btDiscreteDynamicsWorld, double precision, fixed sub-steps, no sleeping";
    info.version = versionText();
    info.settings = bulletSettingSpecs();
    info.create = &create;
    BackendRegistry::global().add(std::move(info));
}

}  // namespace vroc::bullet
