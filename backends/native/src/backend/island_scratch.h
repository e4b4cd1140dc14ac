// SPDX-License-Identifier: MIT
// Storage the island stage (island_step.cpp) reuses from one internal step to the next, so that a
// settled scene's steps allocate nothing there (issue 22): every buffer is emptied, never freed.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "dynamics/contact.h"
#include "dynamics/contact_solver.h"
#include "dynamics/rigid_body.h"
#include "scheduling/impulse_waves.h"

namespace vroc::native {

/// What an island's collision phase did: its troubles (counted as warnings by the caller) and which
/// of its bodies an impulse changed.
struct CollisionPhaseReport {
    std::uint64_t ill_conditioned = 0, degenerate = 0, nonfinite = 0;
    std::vector<std::uint32_t> impulsed;  ///< per body of the island: the impulses that changed it
    /// Per manifold: its two bodies' `impulsed` counts when it last applied none (a later sweep
    /// that finds them unchanged would apply none again: it is passed over), or kUnsettled.
    std::vector<std::uint64_t> settled;
    static constexpr std::uint64_t kUnsettled = ~std::uint64_t{0};
};

/// One worker's count of a collision phase's troubles (summed into CollisionPhaseReport), on a
/// cache line of its own.
struct alignas(64) CollisionTally {
    std::uint64_t ill_conditioned = 0, degenerate = 0, nonfinite = 0;
    double fastest = 0.0;   ///< [m/s] the fastest approach an impulse met in this sweep
};

/// Most workers that share one collision phase (more: one worker runs it).
constexpr int kMaxCollisionTeam = 64;

/// One island's contact phase, computed on local copies (so islands can run on any worker).
struct IslandSolve {
    int root = -1;                        // the island's union-find root (islands run in root order)
    std::vector<int> bodies;              // ascending global indices
    std::vector<int> manifolds;           // indices into the step's manifold list
    std::vector<RigidBody> local;         // per local body: after the collision phase
    std::vector<BodyImpulse> impulses;    // per local body
    std::vector<ContactManifold> solved;  // per local manifold, with outputs
    std::vector<std::uint8_t> resting;    // per local manifold
    CollisionPhaseReport collision;
    ImpulseWaves waves;                   // the collision phase's waves, when a team shares it
    ContactSolverReport report;

    /// Empties it for another island, keeping the storage.
    void reset(int island_root) {
        root = island_root;
        bodies.clear();
        manifolds.clear();
        local.clear();
        impulses.clear();
        solved.clear();
        resting.clear();
        collision.ill_conditioned = collision.degenerate = collision.nonfinite = 0;
        collision.impulsed.clear();
        collision.settled.clear();
        report = ContactSolverReport{};
    }
};

struct IslandScratch {
    std::vector<std::uint8_t> due_root;         // per body: the island it roots is due
    std::vector<int> more;                      // touching pairs of due islands still to sample
    std::vector<int> first_manifold;            // per sample: its first manifold in `manifolds` (and the total)
    std::vector<ContactManifold> manifolds;     // the step's manifolds
    std::vector<std::pair<int, int>> cache_of;  // (pair, part pair) per manifold
    std::vector<Pose> frame_a;                  // per manifold: body A's scene frame at the step's time
    std::vector<std::uint8_t> resting;          // per manifold
    std::vector<std::pair<int, int>> solved_at; // per manifold: its island's pool slot and local index
    std::vector<IslandSolve> pool;              // this step's islands in [0, used)
    std::size_t used = 0;
    std::vector<int> slot_of_root;  // per body: its island's pool slot this step, or -1
    std::vector<IslandSolve*> work, shared, spread;
    std::vector<int> touches;  // per body: manifolds this step (deferImpacts)
    std::vector<int> kicked;   // fixed ticks: bodies a collision impulse changed this step (fixedTick)
    IslandSolve impact;        // fixed ticks: the new manifolds of an impact pass (impactPass)
    // Local protection solves (native.protection_ring): per body, its ring (touching steps from a
    // body whose tick came; -1 outside), whether it is held as ground, whether its island is solved
    // locally (per root); the breadth-first queue.
    std::vector<int> ring;
    std::vector<std::uint8_t> held_ground;
    std::vector<std::uint8_t> local_root;
    std::vector<int> ring_queue;
    bool local_marked = false;   // the last markLocalSolves marked bodies (the per-body vectors need clearing)
};

}  // namespace vroc::native
