// SPDX-License-Identifier: MIT
#pragma once

#include "checks/check_result.h"
#include "vroc/core/backend.h"

namespace vroc::conformance {

/// applyImpulse against the closed form (docs/backend-contract.md): on a free irregular hull turned
/// 0.7 rad away from identity (so that body frame and world frame differ), an impulse J at world
/// point p changes the momentum by exactly J and the angular momentum about the centre of mass by
/// (p - com) x J, both in the world frame, and moves nothing. Rejects a backend that reads J in
/// the body frame (broken_backends/wrong_frame_impulse_backend.h).
CheckResult checkImpulse(const BackendInfo& backend);

}  // namespace vroc::conformance
