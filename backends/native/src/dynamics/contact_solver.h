// SPDX-License-Identifier: MIT
// The contact phase of Guendelman, Bridson & Fedkiw 2003: on the velocities predicted for the
// step (gravity added), touching pairs get inelastic (e = 0) impulses with Coulomb friction so that
// no contact point approaches during the step; then shock propagation re-solves the contact graph
// level by level from the static bodies up, with lower levels frozen, so stacks do not sink.
#pragma once

#include <vector>

#include "dynamics/contact.h"
#include "dynamics/rigid_body.h"

namespace vroc::native {

enum class ResponseModel { Vroc1995, NewtonCoulomb };

struct ContactSolverSettings {
    int iterations = 20;          ///< Gauss-Seidel sweeps over all contact points
    int shock_iterations = 8;     ///< sweeps per level during shock propagation (0 = off)
    ResponseModel model = ResponseModel::NewtonCoulomb;
};

/// Per body: the impulses the contact phase applies over the step.
struct BodyImpulse {
    Vec3 linear = Vec3::Zero();    ///< [N s] sum of impulses, world
    Vec3 angular = Vec3::Zero();   ///< [N m s] sum of (p - com) x impulse, world
    bool supported = false;        ///< a contact impulse acted on the body this step
};

struct ContactSolverReport {
    int points = 0;                ///< contact points solved
    int ill_conditioned = 0;       ///< single-point solves that fell back
};

/// Solves the contact phase for a step of `h` [s]. Bodies are read, not changed; the result is
/// the impulses per body (same indexing as `bodies`) and each manifold's contact_impulse.
ContactSolverReport solveContactPhase(const std::vector<RigidBody>& bodies,
                                      std::vector<ContactManifold>& manifolds, double h,
                                      const Vec3& gravity, const ContactSolverSettings& settings,
                                      std::vector<BodyImpulse>& impulses);

}  // namespace vroc::native
