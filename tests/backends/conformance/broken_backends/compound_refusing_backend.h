// SPDX-License-Identifier: MIT
// Not broken: the control. It declares compounds unsupported and refuses every scene with one,
// with an InputError naming the body, before anything is built (docs/backend-contract.md,
// Creation); everything else is native. No real backend refuses a shape kind today, so this is
// what shows the refusal branch of checkShapeSupport and checkShippedScenes passing a backend
// that keeps to the contract; it must pass every check.
#pragma once

#include <memory>

#include "broken_backends/delegating_backend.h"
#include "vroc/core/errors.h"

namespace vroc::conformance {

inline BackendInfo compoundRefusingBackend() {
    BackendInfo info = wrappedNativeInfo(
        "compound_refusing", [](const Scene& scene, const Settings& settings) -> std::unique_ptr<Backend> {
            for (const Body& b : scene.bodies)
                if (b.shape.kind == Shape::Kind::Compound)
                    throw InputError("scene '" + scene.name + "', body '" + b.name +
                                     "': compound shapes are not supported by compound_refusing");
            return nativeInfo().create(scene, settings);
        });
    info.description = "test double: the native backend that declares compounds unsupported and refuses them";
    info.capabilities.compound = Support::Unsupported;
    return info;
}

}  // namespace vroc::conformance
