// SPDX-License-Identifier: MIT
#pragma once

#include "checks/check_result.h"
#include "vroc/core/backend.h"

namespace vroc::conformance {

/// What the shipped-scenes check asks of each scene.
struct ShippedScenesCheckOptions {
    int finite_frames = 2;     ///< frames stepped before the states must be finite
    double kick_speed = 0.3;   ///< [m/s] upward (against gravity) speed given to the kicked body at t = 0
    double min_rise = 0.0015;  ///< [m] its centre of mass must rise at least this much ...
    double max_time = 0.1;     ///< [s] ... and, with gravity, come back down within this time
    bool stress_scenes = true;  ///< also the scenes under scenes/stress/
    // At 1/60 s frames the first frame lifts the body 3.6 mm in exact flight and 2.3 mm in
    // symplectic Euler (Bullet, ODE: one step per frame); the upward velocity is 0.3 - g t at a
    // frame's end in either, negative from t = 0.031 s on. Both show within the 2 finite frames;
    // max_time allows three times that and keeps a failing dense scene from costing seconds.
};

/// Every shipped scene is created, or refused with InputError when it needs a feature the backend
/// declares unsupported; it steps to finite states at the summed frame time; and things move: the
/// highest virtual body, its velocity set to `kick_speed` upward at t = 0, rises by `min_rise`
/// and, under gravity, falls back (its upward velocity turns negative) within `max_time`. A kick rather than
/// waiting for gravity alone, because a stack at rest in an exact backend does not move at all
/// (native's pyramids stay put to 1e-18 m). Rejects a backend whose bodies do not move
/// (broken_backends/frozen_backend.h).
CheckResult checkShippedScenes(const BackendInfo& backend, const ShippedScenesCheckOptions& options = {});

}  // namespace vroc::conformance
