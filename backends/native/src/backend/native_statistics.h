// SPDX-License-Identifier: MIT
// Counters of the native backend, reported through Backend::statistics() into run.json.
#pragma once

#include <algorithm>
#include <cstdint>

#include "vroc/core/backend.h"
#include "vroc/core/backend_vocabulary.h"

namespace vroc::native {

struct NativeStatistics {
    std::int64_t frames = 0;
    std::int64_t internal_steps = 0;
    std::int64_t max_internal_steps_per_frame = 0;
    std::int64_t broad_phase_pairs = 0;      ///< summed over internal steps
    std::int64_t narrow_queries = 0;         ///< part-pair proximity queries
    std::int64_t carried_manifolds = 0;      ///< touching part pairs carried by their anchors instead of queried
    std::int64_t walk_steps = 0;             ///< summed over queries
    std::int64_t max_walk_steps = 0;
    std::int64_t step_solves = 0;            ///< contact-phase solves, one per island solved
    std::int64_t flight_pair_queries = 0;    ///< flight pairs queried (their key came, or a body changed)
    std::int64_t collisions = 0;             ///< collision events
    std::int64_t contacts = 0;               ///< touching part pairs, summed over internal steps
    std::int64_t contact_points = 0;         ///< contact-phase points, summed over internal steps
    std::int64_t speculative_points = 0;     ///< of those, points beyond the collision distance
    std::int64_t contact_sweeps = 0;         ///< contact-phase sweeps run (they stop at the tolerance)
    std::int64_t shock_sweeps = 0;           ///< shock-propagation sweeps run, summed over levels
    std::int64_t position_corrections = 0;   ///< patches the split-impulse pass pushed back to the window
    std::int64_t max_island_bodies = 0;      ///< bodies (static ones included) of the largest island solved
    std::int64_t islands_slept = 0;          ///< islands put to sleep (native.sleeping)
    /// Why each island solve ran (they add up to step_solves): its tick came on the grid of
    /// sub-steps; its tick came off the grid (a protection tick: a touching pair could otherwise
    /// close too far before the next grid tick); or a contact appeared in it before its tick.
    std::int64_t solves_on_grid = 0;
    std::int64_t solves_protection = 0;
    std::int64_t solves_new_contact = 0;
    /// Of the protection ticks, those that solved only the bodies near the due ones
    /// (native.protection_ring), and the bodies they held as ground.
    std::int64_t solves_local = 0;
    std::int64_t local_held_bodies = 0;
    std::int64_t solved_island_bodies = 0;  ///< bodies of the islands solved, summed over solves
    std::int64_t fixed_impact_passes = 0;   ///< fixed ticks: passes after an impact set bodies moving
    std::int64_t fixed_looked_ticks = 0;   ///< fixed ticks: ticks with a pair that may close beyond its reach
    std::int64_t fixed_tick_looks = 0;     ///< fixed ticks: looks inside ticks at such pairs
    std::int64_t fixed_looks_cut = 0;      ///< fixed ticks: pairs that reached native.max_tick_looks in a tick
    std::int64_t fixed_look_solves = 0;    ///< fixed ticks: islands solved at a look (a pair in flight met)
    std::int64_t bounded_pairs = 0;   ///< fixed ticks: pair queries skipped, bounded beyond reach (pair_bounds)
    /// [m] deepest penetration a pair's sample found (before a contact phase pushed it out)
    double deepest_penetration = 0.0;

    /// Shared names (docs/backend-contract.md) as they are; the rest get the "native." prefix.
    Statistics report() const {
        Statistics s;
        const double steps = static_cast<double>(std::max<std::int64_t>(1, internal_steps));
        const double queries = static_cast<double>(std::max<std::int64_t>(1, narrow_queries));
        s["frames"] = static_cast<double>(frames);
        s["internal_steps"] = static_cast<double>(internal_steps);
        s["internal_steps_per_frame_mean"] =
            static_cast<double>(internal_steps) / static_cast<double>(std::max<std::int64_t>(1, frames));
        s["internal_steps_per_frame_max"] = static_cast<double>(max_internal_steps_per_frame);
        s["broadphase_pairs_mean"] = static_cast<double>(broad_phase_pairs) / steps;
        s["narrow_queries"] = static_cast<double>(narrow_queries);
        s["carried_manifolds"] = static_cast<double>(carried_manifolds);
        s["walk_steps_mean"] = static_cast<double>(walk_steps) / queries;
        s["walk_steps_max"] = static_cast<double>(max_walk_steps);
        s["contact_solves"] = static_cast<double>(step_solves);
        s["flight_pair_queries"] = static_cast<double>(flight_pair_queries);
        s["collision_events"] = static_cast<double>(collisions);
        s["contacts"] = static_cast<double>(contacts);
        s["contact_points_solved"] = static_cast<double>(contact_points);
        s["speculative_points"] = static_cast<double>(speculative_points);
        s["contact_points_mean"] = static_cast<double>(contact_points) / steps;
        s["contact_sweeps_per_solve"] =
            static_cast<double>(contact_sweeps) / static_cast<double>(std::max<std::int64_t>(1, step_solves));
        s["shock_sweeps_per_solve"] =
            static_cast<double>(shock_sweeps) / static_cast<double>(std::max<std::int64_t>(1, step_solves));
        s["position_corrections"] = static_cast<double>(position_corrections);
        s["max_island_bodies"] = static_cast<double>(max_island_bodies);
        s["islands_slept"] = static_cast<double>(islands_slept);
        s["solves_on_grid"] = static_cast<double>(solves_on_grid);
        s["solves_protection"] = static_cast<double>(solves_protection);
        s["solves_local"] = static_cast<double>(solves_local);
        s["local_held_bodies"] = static_cast<double>(local_held_bodies);
        s["solves_new_contact"] = static_cast<double>(solves_new_contact);
        s["solved_bodies_per_solve"] =
            static_cast<double>(solved_island_bodies) / static_cast<double>(std::max<std::int64_t>(1, step_solves));
        s["deepest_penetration_m"] = deepest_penetration;
        s["fixed_impact_passes"] = static_cast<double>(fixed_impact_passes);
        s["fixed_looked_ticks"] = static_cast<double>(fixed_looked_ticks);
        s["fixed_tick_looks"] = static_cast<double>(fixed_tick_looks);
        s["fixed_looks_cut"] = static_cast<double>(fixed_looks_cut);
        s["fixed_look_solves"] = static_cast<double>(fixed_look_solves);
        s["bounded_pairs"] = static_cast<double>(bounded_pairs);
        return vocabulary::prefixed(s, "native");
    }
};

}  // namespace vroc::native
