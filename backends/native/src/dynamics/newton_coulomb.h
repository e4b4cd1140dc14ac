// SPDX-License-Identifier: MIT
// Newton restitution with Coulomb friction for one contact point (the collision phase of
// Guendelman, Bridson & Fedkiw 2003): the normal relative velocity is reversed and scaled by e;
// the tangential relative velocity is stopped if the impulse stays inside the circular cone
// (sticking), else the impulse slides on the cone's surface opposite the slip direction.
#pragma once

#include "dynamics/impulse_result.h"
#include "dynamics/rigid_body.h"

namespace vroc::native {

/// [m/(N s)] the collision matrix K: relative velocity change at `p` per unit impulse on B (-on A).
Mat3 collisionMatrix(const RigidBody& a, const RigidBody& b, const Vec3& p);

/// Impulse for a point `p` [m, world] with normal `n` (A -> B). Zero if the bodies separate there.
ImpulseResult newtonCoulombImpulse(const RigidBody& a, const RigidBody& b, const Vec3& p,
                                   const Vec3& n, double restitution, double friction);

}  // namespace vroc::native
