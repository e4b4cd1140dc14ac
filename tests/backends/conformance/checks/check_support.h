// SPDX-License-Identifier: MIT
// Small pieces every conformance check uses: creating a backend from its BackendInfo (the factory
// a check is handed), reading all states, and the shipped scenes.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "vroc/core/backend.h"
#include "vroc/core/scene.h"

namespace vroc::conformance {

/// `key=value` settings on top of a backend's defaults (resolveSettings).
using SettingOverrides = std::vector<std::pair<std::string, std::string>>;

/// backend.create on `scene` with its default settings plus `overrides`.
std::unique_ptr<Backend> createBackend(const BackendInfo& backend, const Scene& scene,
                                       const SettingOverrides& overrides = {});

std::vector<BodyState> statesOf(const Backend& b);
bool finite(const BodyState& s);
/// The same rotation (q and -q are), to `tol` per quaternion component.
bool sameRotation(const Quat& a, const Quat& b, double tol);
/// [m] world position of body `body`'s centre of mass in state `s`.
Vec3 centreOfMass(const Body& body, const BodyState& s);
/// [m] the lowest point of `shape` along world z when its frame is at `pose` (a support point).
double lowestZ(const Shape& shape, const Pose& pose);

/// Every scene under scenes/ (recursively), sorted.
std::vector<std::filesystem::path> shippedScenes();

struct ShippedScene {
    std::filesystem::path path;
    Scene scene;
};
/// shippedScenes(), loaded once per process: several checks on many backends read them, and the
/// large ones take a tenth of a second each to parse.
const std::vector<ShippedScene>& loadedShippedScenes();
/// A shipped scene by its path below scenes/ ("staircase.json", "stress/pyramid10.json").
Scene shippedScene(const std::string& relative_path);

}  // namespace vroc::conformance
