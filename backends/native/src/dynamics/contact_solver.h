// SPDX-License-Identifier: MIT
// The contact phase of Guendelman, Bridson & Fedkiw 2003: on the velocities predicted for the
// step (gravity added), touching pairs get inelastic (e = 0) impulses with Coulomb friction so that
// no contact point approaches during the step; then shock propagation re-solves the contact graph
// level by level from the static bodies up, with lower levels frozen, so stacks do not sink.
// Warm started: each manifold brings the accumulated impulses of its pair's previous solve
// (Catto 2005), so a resting pile converges in a few sweeps. Penetration is corrected inside the
// solver by a separate pseudo-velocity pass (split impulse): it moves positions only, so it adds no
// kinetic energy and never teleports a body by more than the gap it repairs.
#pragma once

#include <cstddef>
#include <functional>
#include <limits>
#include <vector>

#include "dynamics/contact.h"
#include "dynamics/rigid_body.h"

namespace vroc::native {

enum class ResponseModel { Vroc1995, NewtonCoulomb };

/// Manifolds from which an island's sweeps are shared by a team (ContactSolverSettings::team);
/// below it the barriers between colour groups cost more than the workers save.
constexpr std::size_t kTeamManifolds = 64;

struct ContactSolverSettings {
    int iterations = 10;          ///< Gauss-Seidel sweeps over all contact points
    int cold_factor = 24;         ///< sweeps x this for a large island whose manifolds are mostly cold
    int shock_iterations = 8;     ///< sweeps per level during shock propagation (0 = off)
    /// Shock sweeps per level: at least the island's number of levels (a tall pile's per-level
    /// residuals add up at its top).
    bool shock_per_level = true;
    /// [-] a contact carries a level up only if its normal, pointing to the upper body, rises against
    /// gravity by more than this (the sine of its elevation above the horizontal); -1 (or no
    /// gravity): every contact, so levels are plain graph distances from the bodies of infinite mass.
    double shock_support = 0.0;
    /// Shock sweeps solve each body held only from the frozen levels (and static bodies) as one
    /// block (support_block.h) while its patches stick and push; false: patch by patch.
    bool shock_whole_bodies = true;
    /// [m/s] sweeps (and each level's shock sweeps) stop early once no relaxation in a whole sweep
    /// changed a contact's relative velocity by more than this; 0 runs every sweep.
    double tolerance = 0.0;
    ResponseModel model = ResponseModel::NewtonCoulomb;
    bool warm_start = true;       ///< start from the manifolds' previous impulses
    /// Split-impulse position pass: a patch whose gap is below `correction_floor` [m] is pushed
    /// towards `correction_target` [m] (fraction `correction_rate` of the error per step).
    double correction_floor = 0.0;
    double correction_target = 0.0;
    double correction_rate = 0.8;
    int correction_iterations = 8;   ///< pseudo-velocity Gauss-Seidel sweeps (0 = off)
    /// Speculative points (ContactManifold::point_gap at or above `speculative_from` [m]) may close
    /// to `speculative_target` [m] within the step: they push only when they would be reached then.
    double speculative_from = std::numeric_limits<double>::infinity();
    double speculative_target = 0.0;
    /// Fixed ticks: every target also holds for a body that moves at its end velocity over the
    /// whole step (one whose contact the tick turns into an impact at its start, fixedTick): a
    /// touching point ends not approaching, and a speculative one closes by at most its allowance
    /// at its end speed. Otherwise a separating point may slow down to minus its start speed, and a
    /// speculative one close by twice its allowance at its end speed, which only the mean of the
    /// start and end velocities (a drift) keeps within the allowance.
    bool end_targets = false;
    /// Optional workers for the sweeps of one large island: team(fn) calls fn(worker) for every
    /// worker in [0, team_size) at once and returns when all have returned. Empty: the calling
    /// thread alone. The sweeps visit patches in groups that share no moving body, in an order that
    /// does not depend on the worker count, so the result is bit-identical with or without a team.
    std::function<void(const std::function<void(int)>&)> team;
    int team_size = 1;
};

/// fn(i) for every i in [0, count): by `settings.team` (worker w takes i = w, w + team_size, ...)
/// if `share` and there is a team, else on the calling thread. fn must touch nothing but what
/// belongs to i: then the same bits either way.
template <class Fn>
void forEachOnTeam(const ContactSolverSettings& settings, bool share, std::size_t count, const Fn& fn) {
    if (!share || !settings.team || settings.team_size <= 1) {
        for (std::size_t i = 0; i < count; ++i) fn(i);
        return;
    }
    struct Job {
        std::size_t count, stride;
        const Fn* fn;
    } job{count, static_cast<std::size_t>(settings.team_size), &fn};
    settings.team([&job](int worker) {   // one reference captured: no allocation
        for (std::size_t i = static_cast<std::size_t>(worker); i < job.count; i += job.stride) (*job.fn)(i);
    });
}

/// Per body: the impulses the contact phase applies over the step.
struct BodyImpulse {
    Vec3 linear = Vec3::Zero();    ///< [N s] sum of impulses, world
    Vec3 angular = Vec3::Zero();   ///< [N m s] sum of (p - com) x impulse, world
    bool supported = false;        ///< a contact impulse acted on the body this step
    Vec3 displacement = Vec3::Zero();   ///< [m] split-impulse position correction of the COM, world
                                        ///< (translation only: see positionPass)
    /// The soft step's form (solveSoftStep): the body moves over the step at constant velocity and
    /// angular velocity (its sub-steps' displacement and rotation over the step; `linear` and
    /// `angular` unused) and ends the step at `end_velocity` and `end_angular_velocity`. Between two
    /// states that do not penetrate, a straight path does not either (to first order in rotation);
    /// a parabola through the same end points can.
    bool sub_stepped = false;
    Vec3 mean_velocity = Vec3::Zero();          ///< [m/s] displacement over the step / step
    Vec3 mean_angular_velocity = Vec3::Zero();  ///< [rad/s] rotation vector over the step / step, world
    Vec3 end_velocity = Vec3::Zero();           ///< [m/s]
    Vec3 end_angular_velocity = Vec3::Zero();   ///< [rad/s] world
};

struct ContactSolverReport {
    int points = 0;                ///< contact points solved
    int ill_conditioned = 0;       ///< single-point solves that fell back
    int corrected_patches = 0;     ///< patches below the correction floor (split impulse ran)
    int sweeps = 0;                ///< Gauss-Seidel sweeps run over all patches
    int shock_sweeps = 0;          ///< shock-propagation sweeps run (summed over levels)
};

/// Solves the contact phase for a step of `h` [s]. Bodies are read, not changed; the result is
/// the impulses per body (same indexing as `bodies`), each manifold's contact_impulse and its
/// accumulated impulses (point_impulse, tangent_impulse, torsion_impulse) for the next warm start.
ContactSolverReport solveContactPhase(const std::vector<RigidBody>& bodies,
                                      std::vector<ContactManifold>& manifolds, double h,
                                      const Vec3& gravity, const ContactSolverSettings& settings,
                                      std::vector<BodyImpulse>& impulses);

}  // namespace vroc::native
