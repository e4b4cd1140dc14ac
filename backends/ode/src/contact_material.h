// SPDX-License-Identifier: MIT
// The scene's material rule (scene.h: combineMaterials: restitution = min, friction = geometric
// mean) as ODE contact surface parameters. ODE has no material objects: every contact joint
// carries its own dSurfaceParameters, filled here per contact from the two bodies' materials.
//
//  - Friction: mode dContactApprox1 bounds each of the two friction rows by mu x the contact's
//    normal force (a 4-sided friction pyramid, axes from dPlaneSpace(normal)). Without it ODE
//    bounds friction by mu in newtons, which cannot express a Coulomb coefficient.
//  - Restitution: dContactBounce with bounce = e. ODE applies it to a contact whose approach speed
//    at the start of the step exceeds bounce_vel: the solved separating speed is at least
//    e x the approach speed (docs/ode-backend.md).
#pragma once

#include <ode/ode.h>

#include "vroc/core/scene.h"

namespace vroc::ode {

/// Surface parameters of a contact between bodies of materials `a` and `b`.
/// `bounce_vel` [m/s]: approach speeds at or below it do not bounce.
dSurfaceParameters surfaceFor(const Material& a, const Material& b, double bounce_vel);

}  // namespace vroc::ode
