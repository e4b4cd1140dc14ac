// SPDX-License-Identifier: MIT
#pragma once

#include "checks/check_result.h"
#include "vroc/core/backend.h"

namespace vroc::conformance {

/// What a backend says about itself is complete and consistent: every Approximated feature
/// (sphere, box, hull, compound, restitution, tracked) has a non-empty note saying how, and no
/// Exact one has a note (a note says how a feature differs; an exact one does not); the version
/// and precision are named; each deviation says why ("what: why"). The behaviour behind the
/// declarations is held by checkShapeSupport and checkLanding. Rejects a backend that approximates
/// without saying how (broken_backends/unexplained_approximation_backend.h).
CheckResult checkCapabilityNotes(const BackendInfo& backend);

}  // namespace vroc::conformance
