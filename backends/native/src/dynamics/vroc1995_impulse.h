// SPDX-License-Identifier: MIT
// The VROC 1995 response (paper section "Collision response"): single-point contact, impulse R
// from the conservation of linear and angular momentum, scaled by the minimum elasticity.
// The paper's "15x15 system" is read as (docs/response-models.md):
//   unknowns v1', v2', w1', w2', R (3 each = 15),
//   m1 v1' = m1 v1 - R,  m2 v2' = m2 v2 + R,          (R acts on body 2 = B, -R on body 1 = A)
//   I1 w1' = I1 w1 - r1 x R,  I2 w2' = I2 w2 + r2 x R, (r = contact point - COM)
//   closure: the contact points' velocities become equal (a plastic, sticking impact).
// The plastic impulse R0 is then scaled by (1 + e_min) so that e = 0 is plastic and e = 1 reverses
// the whole relative contact velocity (energy conserving).
#pragma once

#include "dynamics/impulse_result.h"
#include "dynamics/rigid_body.h"

namespace vroc::native {

/// Impulse on B at `p` [m, world]; zero if the bodies separate along `n` (A -> B) there.
ImpulseResult vroc1995Impulse(const RigidBody& a, const RigidBody& b, const Vec3& p, const Vec3& n,
                              double restitution);

/// The plastic impulse R0 from the literal 15x15 linear system (exposed for tests).
ImpulseResult vroc1995PlasticImpulse(const RigidBody& a, const RigidBody& b, const Vec3& p);

}  // namespace vroc::native
