// SPDX-License-Identifier: MIT
#pragma once

#include "checks/check_result.h"
#include "vroc/core/backend.h"

namespace vroc::conformance {

/// What the landing check asks of each dropped body.
struct LandingCheckOptions {
    double drop_height = 0.1;              ///< [m] lowest point above the floor at release, at rest
    double duration = 1.5;                 ///< [s] simulated before the rest is measured
    double exact_tolerance = 0.002;        ///< [m] rest gap error allowed for a shape declared Exact
    double approximated_tolerance = 0.01;  ///< [m] ... for one declared Approximated (its note says how)
    double rest_speed = 0.05;              ///< [m/s] the body's centre of mass is slower than this at the end
};

/// Something touches: a body of each shape kind the backend does not declare unsupported (sphere,
/// box, hull, compound; restitution 0, so no restitution support is needed), dropped flat onto a
/// real floor, reports a collision event with the floor and comes to rest on it: its lowest point
/// ends within the shape's tolerance of the floor's top face (the gap may be up to the scene's
/// collision distance). The expected rest height is geometry alone (a support point), not another
/// backend's output. Rejects a backend whose bodies pass through the floor
/// (broken_backends/no_contacts_backend.h), one whose bodies never fall (frozen_backend.h) and one
/// that declares hulls exact but collides them as their bounding spheres (wrong_capability_backend.h).
CheckResult checkLanding(const BackendInfo& backend, const LandingCheckOptions& options = {});

}  // namespace vroc::conformance
