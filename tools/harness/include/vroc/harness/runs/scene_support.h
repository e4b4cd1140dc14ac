// SPDX-License-Identifier: MIT
// Whether a backend can represent a scene faithfully, from its declared capabilities
// (docs/backend-contract.md): the harness reports "not supported" or "approximated: why" instead
// of a silent pass or a crash.
#pragma once

#include <string>
#include <vector>

#include "vroc/core/backend.h"
#include "vroc/core/scene.h"

namespace vroc::harness {

struct SceneSupport {
    Support level = Support::Exact;   ///< the worst over every feature the scene uses
    std::string reason;               ///< empty when Exact: "hull: <note>; restitution: <note>"
};

/// Features used: the shape kinds of every body (and of compound parts), and restitution when a
/// material has e > 0. Unsupported beats Approximated beats Exact; the reason names each feature
/// at the worst level with the backend's note.
SceneSupport sceneSupport(const Scene& scene, const BackendCapabilities& capabilities);

/// What a run actually exercised (honest labels, issue 23): the shapes of the bodies that touched
/// something (from the run's collision events), restitution where a touching pair's material has
/// e > 0, the friction law where a touching pair has mu > 0 and the backend's law is not Coulomb's
/// cone ("friction": its note), and tracked bodies. A run with no collision event exercised no
/// contact feature: a ball in flight is exact on every backend.
SceneSupport exercisedSupport(const Scene& scene, const BackendCapabilities& capabilities,
                              const std::vector<CollisionEvent>& events);

/// "exact", "approximated: <reason>" or "not supported: <reason>".
std::string supportText(const SceneSupport& s);

}  // namespace vroc::harness
