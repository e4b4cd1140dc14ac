// SPDX-License-Identifier: MIT
// The native backend's settings (`--set native.<name>=value`), declared with type, range and help.
#pragma once

#include <algorithm>
#include <vector>

#include "dynamics/contact_solver.h"
#include "vroc/core/settings.h"

namespace vroc::native {

/// How a touching island is scheduled between its grid ticks (docs/native-dynamics.md, "Two regimes").
enum class TouchingRegime {
    /// Fixed step: the island is solved on the sub-step grid only; features that may close within a
    /// tick enter its solve as speculative points (they act when they would be reached).
    Speculative,
    /// Event-driven protection: the island is solved again whenever a feature could close past the
    /// window (motion bounds), the schedule of issue 9.
    Protected,
    /// Fixed step with Box2D v3's soft step inside each tick (sub-steps, soft push-out, relax):
    /// held pairs are solved on the grid only, with no protection tick for what is in reach.
    Soft,
    /// Fixed ticks (contact_substeps per frame), Box2D's and Bullet's schedule: at every tick every
    /// pair within reach of what it may close in the tick is sampled and its island solved (the
    /// block contact phase); no event, no protection tick. A body with no pair in reach flies exactly.
    Fixed,
    /// Fixed ticks with Box2D v3's soft step as each tick's contact phase.
    FixedSoft,
};

/// Held islands are solved on the grid with speculative points (every regime but protected).
inline bool onGrid(TouchingRegime r) { return r != TouchingRegime::Protected; }
/// Every pair is sampled and every island solved at fixed ticks (no event schedule).
inline bool fixedTicks(TouchingRegime r) { return r == TouchingRegime::Fixed || r == TouchingRegime::FixedSoft; }
/// The contact phase is Box2D v3's soft step (dynamics/soft_step.h).
inline bool softContact(TouchingRegime r) { return r == TouchingRegime::Soft || r == TouchingRegime::FixedSoft; }

struct NativeSettings {
    ResponseModel response = ResponseModel::NewtonCoulomb;
    int threads = 1;                        ///< workers for the narrow phase (results identical for any)
    int max_internal_steps = 20000;         ///< per frame; beyond it the rest of the frame is one step
    double restitution_threshold = 0.0;     ///< [m/s] approach speeds below it collide with e = 0
    int collision_iterations = 5;           ///< collision-phase sweeps over touching pairs
    /// Collision-phase sweeps while a blow travels (see collisionBlowIterations).
    int collision_blow_iterations = 40;
    int contact_iterations = 10;            ///< contact-phase Gauss-Seidel sweeps
    int shock_iterations = 8;               ///< shock-propagation sweeps per level (0 = off)
    bool shock_per_level = true;            ///< at least as many shock sweeps a level as the island has levels
    /// [-] a contact passes a shock level up only if its normal, towards the upper body, rises against
    /// gravity by more than this (sine of its elevation); -1: any contact (levels from every static body)
    double shock_support = 0.0;
    bool shock_whole_bodies = true;         ///< shock sweeps solve a body held from the frozen levels as one block
    double solver_tolerance = 0.0;          ///< [m/s] contact sweeps stop once a sweep changes no velocity more
    int contact_substeps = 1;               ///< island ticks per frame (the contact phase's step)
    TouchingRegime touching = TouchingRegime::Protected;   ///< how touching islands are scheduled (speculative: experimental)
    bool warm_start = true;                 ///< contact phase starts from the previous impulses
    /// A protection tick (off the grid) solves the bodies within this many touching steps of a body
    /// whose tick came, with the next ring held as ground; -1: the whole island
    int protection_ring = -1;
    /// [-] fraction of the collision distance: a touching pair whose bodies moved less than this
    /// relative to each other since its last query keeps that manifold, carried along (0: query always)
    double manifold_reuse = 0.02;
    /// [-] fraction of the smaller body's inner radius: the farthest beyond the collision distance a
    /// feature enters a pair's solve in the regimes with speculative points; -1: the regime's own
    /// (0.25 speculative and soft, 1 with fixed ticks: speculativeReach())
    double speculative_reach = -1.0;
    /// The cap native.speculative_reach stands for in this regime.
    double speculativeReach() const {
        return speculative_reach >= 0.0 ? speculative_reach : (fixedTicks(touching) ? 1.0 : 0.25);
    }
    /// After collision_iterations sweeps, the collision phase sweeps on, up to this many, while a
    /// sweep's fastest impulse met an approach faster than gravity adds in a tick: a blow running
    /// along a row of touching bodies (a 10 kg ball into a row of 1 kg boxes passes its momentum on
    /// one box per sweep). In every regime: in the event-driven ones a pair the phase leaves
    /// approaching is repaired beyond the collision distance, and on fixed ticks the contact phase
    /// stops it only at the tick's end, once it has sunk (SimBenchmark 666's pile landing in one
    /// tick: a column of six balls sank 1.4 mm into the floor with no blow sweeps).
    int collisionBlowIterations() const { return std::max(collision_iterations, collision_blow_iterations); }
    /// Fixed ticks: most ticks a frame is split into where a fast pair needs more than contact_substeps
    int max_fixed_ticks = 4;
    /// Fixed ticks: a pair apart is not queried while a lower bound on its distance (its last one,
    /// minus how far its bodies' points have moved since) stays beyond its reach (false: every pair
    /// queried at every tick; the same motion to rounding, for checking and measurement)
    bool pair_bounds = true;
    /// Fixed ticks: the most looks inside one tick at a pair that may close farther within it than
    /// its patch reaches (conservative advancement to the collision distance); 0: none
    int max_tick_looks = 64;
    /// [-] fraction of the collision distance. Fixed ticks: a pair with a manifold whose points are
    /// predicted (to second order: each body's acceleration, and the turn of the face that holds a
    /// point) to close within the tick by more than this below their gap, or from a gap to touching,
    /// is looked at when they would; 0: no such looks
    double tick_look_depth = 0.5;
    /// Fixed ticks: a touching pair that may close by tick_look_depth within the tick, none of whose
    /// manifold points is predicted to, has its distance predicted at the tick's end (a query at the
    /// bodies' predicted poses) and is looked at when it first sinks so: a feature no patch holds (a
    /// tumbling box whose edge contact turns into another face's); false: manifold points only
    bool tick_look_features = true;
    int soft_substeps = 4;                  ///< soft regime: sub-steps per island tick
    double soft_hertz = 60.0;               ///< [Hz] soft regime: stiffness of the push-out
    int soft_iterations = 4;                ///< soft regime: relaxations with the push-out per sub-step
    int soft_relax = 1;                     ///< soft regime: relaxations without bias per sub-step
    double soft_damping = 1.0;              ///< soft regime: damping ratio of the push-out
    bool sleeping = false;                  ///< islands at rest stop being simulated until touched
    double sleep_speed = 0.01;              ///< [m/s] a body is still below it (COM and |w| x radius)
    double sleep_time = 0.5;                ///< [s] an island sleeps once every body was still this long

    static std::vector<SettingSpec> specs();
    static NativeSettings from(const Settings& settings);
};

}  // namespace vroc::native
