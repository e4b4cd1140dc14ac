// SPDX-License-Identifier: MIT
#pragma once

#include "checks/check_result.h"
#include "vroc/core/backend.h"

namespace vroc::conformance {

/// Declared support holds at creation (docs/backend-contract.md, Creation): for each shape kind
/// (sphere, box, hull, compound) and for a tracked body, a backend that declares it Unsupported
/// refuses a scene that needs it with an InputError naming the body; one that declares it Exact or
/// Approximated creates the scene and steps it 10 frames to finite states. Rejects a backend that
/// declares compounds unsupported yet runs them (broken_backends/accepts_unsupported_backend.h);
/// passes one that declares them unsupported and refuses them (compound_refusing_backend.h).
CheckResult checkShapeSupport(const BackendInfo& backend);

}  // namespace vroc::conformance
