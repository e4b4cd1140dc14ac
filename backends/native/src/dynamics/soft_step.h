// SPDX-License-Identifier: MIT
// The contact phase of the soft regime (native.touching=soft): Box2D v3's soft step (Catto,
// "Solver2D", 2024) on one island's tick. Contact constraints are prepared once per tick (anchors,
// effective masses, the separation of each point); the tick is then cut into sub-steps, each of
// which integrates gravity, warm starts, relaxes the contacts (rigid rows; a penetrating point is
// pushed out at the bias rate of Box2D's soft constraint, a spring of `contact_hertz` with damping
// ratio `damping_ratio`, capped at `max_push_speed`), moves the bodies and relaxes again without the
// push-out, from the top of the pile down. A point's separation is updated in every sub-step from the
// bodies' own motion (their displacement and rotation since the tick began): no new query. A
// point that is apart may close to `target` within the sub-step and no further (a speculative
// contact), so a tumbling vertex that is in the manifold is met when it arrives, without a solve of
// its own. Friction is Coulomb per point (two tangents, the disc of radius mu x normal impulse).
#pragma once

#include <vector>

#include "dynamics/contact.h"
#include "dynamics/contact_solver.h"
#include "dynamics/rigid_body.h"

namespace vroc::native {

struct SoftStepSettings {
    int substeps = 4;             ///< sub-steps per tick
    int iterations = 1;           ///< relaxations with the soft bias per sub-step, before the move
    int relax_iterations = 1;     ///< relaxations without bias after each sub-step's move
    double contact_hertz = 30.0;  ///< [Hz] stiffness of the push-out (capped at a quarter of the sub-step rate)
    double damping_ratio = 10.0;  ///< [-] of the push-out spring (Box2D's default: overdamped)
    double max_push_speed = 3.0;  ///< [m/s] fastest push-out of a penetrating point
    double target = 0.0;          ///< [m] separation a penetrating point is pushed out to
    /// [m] a point at or beyond this separation is speculative: it may close to `target` within the
    /// tick; a point closer is held where it is (no further approach).
    double speculative_from = 0.0;
    /// [m] below this separation at the start a manifold counts as corrected (the push-out acts).
    double correction_floor = 0.0;
    bool warm_start = true;
};

/// Solves the contact phase of a tick of `h` [s] on the island's `bodies` (read, not changed).
/// Per body with a contact point, `impulses` receives how it moves over the tick, in the form the
/// drift takes (BodyImpulse::sub_stepped): its sub-steps' mean velocity and angular velocity (the
/// displacement and rotation vector over the tick, / h) and their end velocities. Each
/// manifold gets its contact_impulse (summed over the tick) and its accumulated impulses for the
/// next warm start (per tick, as the persistent manifolds store them).
ContactSolverReport solveSoftStep(const std::vector<RigidBody>& bodies, std::vector<ContactManifold>& manifolds,
                                  double h, const Vec3& gravity, const SoftStepSettings& settings,
                                  std::vector<BodyImpulse>& impulses);

}  // namespace vroc::native
