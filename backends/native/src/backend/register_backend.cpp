// SPDX-License-Identifier: MIT
#include "backend/native_backend.h"
#include "vroc/core/backend_registry.h"
#include "vroc/native/native_backend.h"

namespace vroc::native {
namespace {

std::unique_ptr<Backend> create(const Scene& scene, const Settings& settings) {
    return std::make_unique<NativeBackend>(scene, NativeSettings::from(settings));
}

// Equal footing: `substeps` contact ticks a frame (flight and impacts stay exact at any rate);
// native's friction is Coulomb's cone on either footing.
std::vector<std::pair<std::string, std::string>> equalFooting(int substeps) {
    return {{"native.contact_substeps", std::to_string(substeps)}};
}

}  // namespace

void registerBackend() {
    BackendInfo info;
    info.name = "native";
    info.description = "Lin-Canny/V-Clip closest features, impulse response, exact time of contact";
    info.version = "native 0.1 (V-Clip walk, Guendelman contact, exact flight)";
    BackendCapabilities& c = info.capabilities;
    c.sphere = Support::Exact;
    c.box = Support::Exact;
    c.hull = Support::Exact;
    c.compound = Support::Exact;
    c.restitution = Support::Exact;
    c.tracked = Support::Exact;
    c.friction = FrictionModel::Cone;
    c.continuous_collision = true;
    c.deterministic = true;
    c.precision = "double";
    // The native backend is VROC's own: its defaults are the reference, it deviates from nothing.
    info.settings = NativeSettings::specs();
    info.create = &create;
    info.equal_footing = &equalFooting;
    BackendRegistry::global().add(std::move(info));
}

}  // namespace vroc::native
