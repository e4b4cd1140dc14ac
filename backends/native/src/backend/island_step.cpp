// SPDX-License-Identifier: MIT
// Islands of the native step: bodies joined by touching pairs are solved together, at their
// island's tick or when a contact appears in it, and nowhere else (docs/native-dynamics.md).
#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "backend/native_backend.h"
#include "dynamics/newton_coulomb.h"
#include "dynamics/patch_impulse.h"
#include "dynamics/soft_step.h"
#include "dynamics/vroc1995_impulse.h"
#include "scheduling/spin_barrier.h"

namespace vroc::native {
namespace {

// A point of a new manifold takes the warm-start impulse of a cached point closer than this
// fraction of the smaller body's outer radius (in A's frame).
constexpr double kMatchFraction = 0.05;
// A resting patch approaching slower than this fraction of g x tick is left to the contact phase.
constexpr double kQuietApproach = 1e-6;

// Applies a one-point impulse `r` at p to a and b (the bodies of m), counting its troubles in
// `tally` and the impulse on the movable ones in `impulsed`; true if it changed them.
bool applyPointImpulse(const ImpulseResult& r, const Vec3& p, RigidBody& a, RigidBody& b, ContactManifold& m,
                       std::vector<std::uint32_t>& impulsed, CollisionTally& tally) {
    if (r.trouble == ImpulseTrouble::IllConditioned) ++tally.ill_conditioned;
    if (r.trouble == ImpulseTrouble::Degenerate) ++tally.degenerate;
    if (!r.impulse.allFinite()) {
        ++tally.nonfinite;
        return false;
    }
    if (r.impulse.isZero(0.0)) return false;
    a.applyImpulse(-r.impulse, p);
    b.applyImpulse(r.impulse, p);
    if (!a.infiniteMass()) ++impulsed[static_cast<std::size_t>(m.body_a)];
    if (!b.infiniteMass()) ++impulsed[static_cast<std::size_t>(m.body_b)];
    m.collision_impulse += std::max(0.0, r.impulse.dot(m.normal));
    return true;
}

// Runs of manifolds a worker takes at a time (PairPartition::forEachShared).
constexpr std::size_t kManifoldShare = 64;

}  // namespace

double NativeBackend::gridTick(double t) const {
    if (fixedTicks(settings_.touching)) return frame_end_ - t;   // the fixed tick (frame_end_ is its end)
    const double step = frame_dt_ / static_cast<double>(settings_.contact_substeps);
    const double end = frame_end_ + step * std::ceil((t + 0.5 * step - frame_end_) / step);
    // Within rounding of a grid point: exactly there (no sliver steps).
    const double h = end - t;
    return std::abs(t + h - frame_end_) <= 1e-9 * frame_dt_ ? frame_end_ - t : h;
}

void NativeBackend::solveIslands(std::vector<PairSample>& samples, double t) {
    // Most steps only move pairs in flight along: no new contact and no island tick due.
    const bool new_contact = std::any_of(samples.begin(), samples.end(), [](const PairSample& s) { return !s.manifolds.empty(); });
    const bool fixed = fixedTicks(settings_.touching);
    if (!new_contact && (fixed || nextTick() > t)) {
        recordSamples(samples);
        for (const PairSample& s : samples) fixed ? markSampled(s) : scheduleSampled(s, t, false);
        return;
    }
    const double cd = scene_.collision_distance;
    // Islands: the touching pairs known so far and the contacts this step found.
    islands_.reset(infinite_mass_);
    for (int p : touching_) islands_.join(pairs_[static_cast<std::size_t>(p)].a, pairs_[static_cast<std::size_t>(p)].b);
    for (const PairSample& s : samples)
        if (!s.manifolds.empty()) islands_.join(pairs_[static_cast<std::size_t>(s.pair)].a, pairs_[static_cast<std::size_t>(s.pair)].b);
    IslandScratch& sc = island_scratch_;
    std::vector<std::uint8_t>& due_root = sc.due_root;
    due_root.assign(bodies_.size(), 0);
    bool any_due = false;
    // Why an island is due (the statistics count it): its tick came, a contact appeared in it.
    constexpr std::uint8_t kTickCame = 1, kNewContact = 2;
    auto markDue = [&](int body, std::uint8_t why) {
        const int root = islands_.islandOf(body);
        if (root >= 0) {
            due_root[static_cast<std::size_t>(root)] |= why;
            any_due = true;
        }
    };
    for (int p : touching_) {
        const PairState& ps = pairs_[static_cast<std::size_t>(p)];
        for (int body : {ps.a, ps.b})
            if (!infinite_mass_[static_cast<std::size_t>(body)] && tick_end_[static_cast<std::size_t>(body)] <= t)
                markDue(body, kTickCame);
    }
    for (const PairSample& s : samples) {
        if (s.manifolds.empty()) continue;
        markDue(pairs_[static_cast<std::size_t>(s.pair)].a, kNewContact);
        markDue(pairs_[static_cast<std::size_t>(s.pair)].b, kNewContact);
    }
    auto islandOfPair = [&](int p) {
        const PairState& ps = pairs_[static_cast<std::size_t>(p)];
        return islands_.islandOf(infinite_mass_[static_cast<std::size_t>(ps.a)] ? ps.b : ps.a);
    };
    // The island's tick ends on the grid of sub-steps (see below); a solve on the grid runs exactly
    // one sub-step to the next grid point.
    const double h = gridTick(t);
    const bool on_grid =
        fixed || std::abs(h - frame_dt_ / static_cast<double>(settings_.contact_substeps)) <= 1e-6 * frame_dt_;
    const bool any_local = markLocalSolves(due_root, kTickCame, t, any_due && !on_grid);
    // A body the step's solve moves: in a due island, and not held as ground by a local solve.
    auto solvesBody = [&](int body) {
        const auto b = static_cast<std::size_t>(body);
        return !any_local || (!infinite_mass_[b] && sc.held_ground[b] == 0 &&
                              (sc.local_root[static_cast<std::size_t>(islands_.islandOf(body))] == 0 || sc.ring[b] >= 0));
    };
    // The due islands' touching pairs are refreshed from their cached features (in a local solve,
    // the pairs of the bodies it moves).
    if (any_due) {
        std::vector<int>& more = sc.more;
        more.clear();
        for (int p : touching_) {
            const PairState& ps = pairs_[static_cast<std::size_t>(p)];
            if (ps.sampled_step != step_index_ && due_root[static_cast<std::size_t>(islandOfPair(p))] &&
                (solvesBody(ps.a) || solvesBody(ps.b)))
                more.push_back(p);
        }
        std::vector<PairSample>& extra = step_extra_;
        samplePairs(more, t, extra);
        samples.insert(samples.end(), std::make_move_iterator(extra.begin()), std::make_move_iterator(extra.end()));
        std::sort(samples.begin(), samples.end(), [](const PairSample& x, const PairSample& y) { return x.pair < y.pair; });
    }
    recordSamples(samples);
    if (!fixed) deferImpacts(samples, t, frame_end_ - t);
    // Fixed ticks: the impact of a body alone against static or tracked ones (a sphere, or a body
    // landing without turning) is met at its refined touching time by a look inside the tick
    // (lookInsideTick), not at the tick's start, up to a tick early.
    if (fixed && !inside_tick_ && settings_.max_tick_looks > 0) {
        deferImpacts(samples, t, frame_end_ - t, true);
        for (const PairSample& s : samples)
            if (s.deferred && s.contact_time < frame_end_) step_deferred_.push_back({s.contact_time, s.pair});
    }
    if (fixed) noteApproach(samples);

    // Manifolds of the due islands, warm started from their pairs' caches.
    // The island's tick ends on the grid of sub-steps (frame_dt / contact_substeps, anchored at the
    // frame end), between half and one and a half sub-steps from now. It may run past the frame
    // end (the bodies are then reported mid-drift): an impact just before a frame end does not cost
    // a sliver solve. On the grid, islands solved off it (at an impact) fall back in step, so all
    // resting islands share their solve times: a settled bin of 100 separate islands is one internal
    // step per sub-step, not one per island.
    std::vector<ContactManifold>& manifolds = sc.manifolds;
    std::vector<std::pair<int, int>>& cache_of = sc.cache_of;  // (pair, part pair) per manifold
    std::vector<Pose>& frame_a = sc.frame_a;
    // Each sample's manifolds at their places in the list (known first): the workers share them.
    std::vector<int>& first_of = sc.first_manifold;
    first_of.resize(samples.size() + 1);
    first_of[0] = 0;
    for (std::size_t k = 0; k < samples.size(); ++k)
        first_of[k + 1] = first_of[k] + static_cast<int>(samples[k].manifolds.size());
    const auto total = static_cast<std::size_t>(first_of.back());
    manifolds.resize(total);
    cache_of.resize(total);
    frame_a.resize(total);
    partition_->forEachShared(samples.size(), kManifoldShare, [&](std::size_t k) {
        const PairSample& s = samples[k];
        if (s.manifolds.empty()) return;
        const PairState& ps = pairs_[static_cast<std::size_t>(s.pair)];
        const Pose fa = bodies_[static_cast<std::size_t>(ps.a)].framePose();
        for (std::size_t j = 0; j < s.manifolds.size(); ++j) {
            const auto m = static_cast<std::size_t>(first_of[k]) + j;
            manifolds[m] = s.manifolds[j];
            cache_of[m] = {s.pair, s.manifold_part[j]};
            frame_a[m] = fa;
        }
    });
    // Each manifold reads its own cache only: the workers share them out, the same bits.
    if (settings_.warm_start)
        partition_->forEachShared(manifolds.size(), kManifoldShare, [&](std::size_t m) {
            const auto [pair, part] = cache_of[m];
            const PairState& ps = pairs_[static_cast<std::size_t>(pair)];
            const double radius = std::min(shapes_[static_cast<std::size_t>(ps.a)].outer_radius,
                                           shapes_[static_cast<std::size_t>(ps.b)].outer_radius);
            warmStartManifold(ps.manifolds[static_cast<std::size_t>(part)], frame_a[m], h, kMatchFraction * radius,
                              manifolds[m]);
        });
    stats_.contacts += static_cast<std::int64_t>(manifolds.size());
    for (const ContactManifold& m : manifolds)
        stats_.speculative_points += std::count_if(m.point_gap.begin(), m.point_gap.end(), [cd](double g) { return !(g < cd); });
    // A contact that persists from the last solve and approaches slower than gravity closes in one
    // tick is resting, not colliding: its approach is stopped with e = 0, which keeps piles from
    // micro-bouncing; impacts (new contacts, or faster) keep their restitution.
    // (Held: its dynamic bodies drifted with the last solve up to now; a ball bouncing freely in
    // the window was not held, and its bounces keep their restitution.)
    auto held = [&](int body) { return heldAt(body, t); };
    std::vector<std::uint8_t>& resting = sc.resting;
    resting.assign(manifolds.size(), 0);
    for (std::size_t m = 0; m < manifolds.size(); ++m)
        resting[m] = pairs_[static_cast<std::size_t>(manifolds[m].pair)].touching && held(manifolds[m].body_a) &&
                             held(manifolds[m].body_b)
                         ? 1
                         : 0;

    // Collision and contact phase, per island (islands share no dynamic body: any worker, same bits).
    // The islands' solves come from a pool kept across steps (slot_of_root: -1 between steps).
    sc.slot_of_root.resize(bodies_.size(), -1);
    sc.used = 0;
    for (std::size_t m = 0; m < manifolds.size(); ++m) {
        const int root = islandOfPair(manifolds[m].pair);
        int& slot = sc.slot_of_root[static_cast<std::size_t>(root)];
        if (slot < 0) {
            if (sc.used == sc.pool.size()) sc.pool.emplace_back();
            slot = static_cast<int>(sc.used++);
            sc.pool[static_cast<std::size_t>(slot)].reset(root);
        }
        IslandSolve& is = sc.pool[static_cast<std::size_t>(slot)];
        is.manifolds.push_back(static_cast<int>(m));
        is.bodies.push_back(manifolds[m].body_a);
        is.bodies.push_back(manifolds[m].body_b);
    }
    std::vector<IslandSolve*>& work = sc.work;
    work.clear();
    for (std::size_t k = 0; k < sc.used; ++k) {
        IslandSolve& is = sc.pool[k];
        sc.slot_of_root[static_cast<std::size_t>(is.root)] = -1;
        std::sort(is.bodies.begin(), is.bodies.end());
        is.bodies.erase(std::unique(is.bodies.begin(), is.bodies.end()), is.bodies.end());
        work.push_back(&is);
    }
    std::sort(work.begin(), work.end(), [](const IslandSolve* x, const IslandSolve* y) { return x->root < y->root; });
    ContactSolverSettings solver;
    solver.model = settings_.response;
    solver.iterations = settings_.contact_iterations;
    solver.shock_iterations = settings_.shock_iterations;
    solver.shock_per_level = settings_.shock_per_level;
    solver.shock_support = settings_.shock_support;
    solver.shock_whole_bodies = settings_.shock_whole_bodies;
    solver.warm_start = settings_.warm_start;
    solver.tolerance = settings_.solver_tolerance;
    // Penetration (deeper than rounding: a patch placed exactly touching is left alone) is pushed
    // back into the window, to cd/4: then the normal comes from the exact closest features again,
    // not from the penetration query, and the band [0, cd/4] absorbs a resting pile's jitter.
    solver.correction_floor = -0.01 * cd;
    solver.correction_target = 0.25 * cd;
    // Speculative points (beyond the window) may close to half the collision distance: where the
    // scenes place resting bodies, inside the window, so they are held from then on.
    if (onGrid(settings_.touching)) {
        solver.speculative_from = cd;
        solver.speculative_target = 0.5 * cd;
    }
    // Fixed ticks turn a contact that changes a body faster than gravity does into an impact at the
    // tick's start (applyContactImpact): its targets must hold for that motion too.
    solver.end_targets = fixed;
    SoftStepSettings soft;
    soft.substeps = settings_.soft_substeps;
    soft.relax_iterations = settings_.soft_relax;
    soft.iterations = settings_.soft_iterations;
    soft.contact_hertz = settings_.soft_hertz;
    soft.damping_ratio = settings_.soft_damping;
    soft.target = solver.correction_target;
    soft.speculative_from = solver.speculative_from;
    soft.correction_floor = solver.correction_floor;
    soft.warm_start = settings_.warm_start;
    const double resting_speed = scene_.gravity.norm() * h;
    // The island's bodies and manifolds in local numbering; a shared island's copies are shared
    // by its team too (forEachOnTeam: each entry its own).
    auto solveOne = [&](IslandSolve& is, const ContactSolverSettings& settings) {
        is.local.resize(is.bodies.size());
        forEachOnTeam(settings, true, is.bodies.size(), [&](std::size_t k) {
            const int id = is.bodies[k];
            RigidBody& local = is.local[k];
            local = bodies_[static_cast<std::size_t>(id)];
            if (sc.held_ground[static_cast<std::size_t>(id)] != 0) {
                // Held as ground by a local solve: infinite mass, moving as its drift does now.
                local.kinematic_angular_velocity = local.angularVelocity();
                local.is_kinematic = true;
            }
        });
        auto localOf = [&](int id) {
            return static_cast<int>(std::lower_bound(is.bodies.begin(), is.bodies.end(), id) - is.bodies.begin());
        };
        is.solved.resize(is.manifolds.size());
        is.resting.resize(is.manifolds.size());
        forEachOnTeam(settings, true, is.manifolds.size(), [&](std::size_t k) {
            const auto m = static_cast<std::size_t>(is.manifolds[k]);
            ContactManifold& lm = is.solved[k];
            lm = manifolds[m];
            lm.body_a = localOf(lm.body_a);
            lm.body_b = localOf(lm.body_b);
            is.resting[k] = resting[m];
        });
        // A shared island's team (settings.team_size workers) shares its collision phase too.
        collisionPhase(is.local, is.solved, is.resting, resting_speed, h, is.collision, settings.team_size, is.waves);
        is.report = softContact(settings_.touching)
                        ? solveSoftStep(is.local, is.solved, h, scene_.gravity, soft, is.impulses)
                        : solveContactPhase(is.local, is.solved, h, scene_.gravity, settings, is.impulses);
    };
    // A large island is solved alone, its sweeps shared by all workers (colour groups, see
    // solveContactPhase); the other islands are shared out, one per worker. Same bits either way.
    std::vector<IslandSolve*>& shared = sc.shared;
    std::vector<IslandSolve*>& spread = sc.spread;
    shared.clear();
    spread.clear();
    for (IslandSolve* is : work) (is->manifolds.size() >= kTeamManifolds ? shared : spread).push_back(is);
    if (!shared.empty() && partition_->workers() > 1) {
        ContactSolverSettings team = solver;
        team.team_size = partition_->workers();
        team.team = [&](const std::function<void(int)>& fn) {
            partition_->run(static_cast<std::size_t>(team.team_size), [&](std::size_t k, int) { fn(static_cast<int>(k)); });
        };
        for (IslandSolve* is : shared) solveOne(*is, team);
    } else {
        for (IslandSolve* is : shared) solveOne(*is, solver);
    }
    if (spread.size() > 1 && manifolds.size() >= 16) {
        // One reference captured: std::function stores it in place (no allocation per step).
        auto solveSpread = [&](std::size_t k) { solveOne(*spread[k], solver); };
        partition_->run(spread.size(), [&solveSpread](std::size_t k, int) { solveSpread(k); });
    } else {
        for (IslandSolve* is : spread) solveOne(*is, solver);
    }

    // Results in island order: collision impulses change the bodies now, contact impulses become
    // drifts, manifolds go back to their caches.
    for (IslandSolve* is : work) {
        warnCollision(is->collision);
        for (std::size_t k = 0; k < is->bodies.size(); ++k) {
            if (is->collision.impulsed[k] == 0) continue;
            const int body = is->bodies[k];
            // Fixed ticks: a body an impact changed faster than gravity does in the tick may now
            // reach a neighbour its pair was sampled too far from (fixedTick's impact passes).
            if (fixed && kickedFaster(bodies_[static_cast<std::size_t>(body)], is->local[k], body, h))
                sc.kicked.push_back(body);
            bodies_[static_cast<std::size_t>(body)] = is->local[k];
            endDrift(body);   // the old drift was for the old velocity: it flies from now until the solve
        }
        ++stats_.step_solves;
        stats_.solved_island_bodies += static_cast<std::int64_t>(is->bodies.size());
        if (fixed)
            ++stats_.solves_on_grid;
        else if ((due_root[static_cast<std::size_t>(is->root)] & kTickCame) == 0)
            ++stats_.solves_new_contact;
        else if (on_grid)
            ++stats_.solves_on_grid;
        else
            ++stats_.solves_protection;
        const bool local = sc.local_root[static_cast<std::size_t>(is->root)] != 0;
        if (local) {
            ++stats_.solves_local;
            for (int body : is->bodies) stats_.local_held_bodies += sc.held_ground[static_cast<std::size_t>(body)];
        }
        stats_.contact_points += is->report.points;
        stats_.contact_sweeps += is->report.sweeps;
        stats_.shock_sweeps += is->report.shock_sweeps;
        stats_.position_corrections += is->report.corrected_patches;
        stats_.max_island_bodies = std::max<std::int64_t>(stats_.max_island_bodies, static_cast<std::int64_t>(is->bodies.size()));
        if (is->report.ill_conditioned > 0) warn("ill_conditioned_solve", static_cast<std::uint64_t>(is->report.ill_conditioned));
        for (std::size_t k = 0; k < is->bodies.size(); ++k) {
            const int body = is->bodies[k];
            if (infinite_mass_[static_cast<std::size_t>(body)] || sc.held_ground[static_cast<std::size_t>(body)] != 0)
                continue;   // held as ground: its drift from its own last solve goes on
            if (asleep_[static_cast<std::size_t>(body)] != 0) wake(body);   // touched: awake again
            if (is->impulses[k].supported && fixed && !is->impulses[k].sub_stepped &&
                impactingContact(body, is->impulses[k], h)) {
                // Fixed ticks: a blow the contact phase passed on (a row struck end on, a pile
                // hit) is an impact at t, not a force over the tick: spread over the tick, the
                // approach it stops would still close by half of it (|u| h / 2). Its pairs are
                // sampled again in the impact passes; support (the contact cancelling gravity)
                // stays a drift, which keeps resting stacks exact.
                applyContactImpact(body, is->impulses[k]);
                sc.kicked.push_back(body);
            } else if (is->impulses[k].supported) {
                startDrift(body, is->impulses[k], t, h);
            } else if (drift_until_[static_cast<std::size_t>(body)] > t) {
                endDrift(body);   // the old contact force is gone
            }
            setTick(body, t + h);
        }
        if (!local) maybeSleep(is->bodies, t);   // a local solve saw part of the island
    }
    // Manifolds take their island's impulses and go back to their caches, each to its own (body
    // A's frame as at the warm start: no impulse moves a body, and the drifts' position
    // corrections come after).
    std::vector<std::pair<int, int>>& solved_at = sc.solved_at;   // (pool slot, local manifold)
    solved_at.resize(manifolds.size());
    for (std::size_t k = 0; k < sc.used; ++k)
        for (std::size_t j = 0; j < sc.pool[k].manifolds.size(); ++j)
            solved_at[static_cast<std::size_t>(sc.pool[k].manifolds[j])] = {static_cast<int>(k), static_cast<int>(j)};
    partition_->forEachShared(manifolds.size(), kManifoldShare, [&](std::size_t m) {
        const auto [slot, local] = solved_at[m];
        const ContactManifold& lm = sc.pool[static_cast<std::size_t>(slot)].solved[static_cast<std::size_t>(local)];
        ContactManifold& out = manifolds[m];
        out.collision_impulse = lm.collision_impulse;
        out.contact_impulse = lm.contact_impulse;
        out.point_impulse = lm.point_impulse;
        out.tangent_impulse = lm.tangent_impulse;
        out.torsion_impulse = lm.torsion_impulse;
        const auto [pair, part] = cache_of[m];
        storeManifold(pairs_[static_cast<std::size_t>(pair)].manifolds[static_cast<std::size_t>(part)], frame_a[m], h,
                      manifolds[m]);
    });
    // Per-sample totals for the events.
    {
        std::size_t m = 0;
        for (PairSample& s : samples)
            for (ContactManifold& sm : s.manifolds) {
                sm.collision_impulse = manifolds[m].collision_impulse;
                sm.contact_impulse = manifolds[m].contact_impulse;
                ++m;
            }
    }
    emitEvents(samples, t);
    for (const PairSample& s : samples) {
        // A part pair that no longer touches forgets its impulses.
        PairState& ps = pairs_[static_cast<std::size_t>(s.pair)];
        if (s.manifolds.empty())
            for (PersistentManifold& pm : ps.manifolds) pm.clear();
        // A pair with a body held as ground was solved against a guess of that body's motion: it
        // keeps the bound of a pair no solve holds.
        const bool against_ground = sc.held_ground[static_cast<std::size_t>(ps.a)] != 0 ||
                                    sc.held_ground[static_cast<std::size_t>(ps.b)] != 0;
        if (fixed)
            markSampled(s);
        else
            scheduleSampled(s, t, !s.manifolds.empty() && !against_ground);
    }
}

void NativeBackend::warnCollision(const CollisionPhaseReport& report) {
    if (report.ill_conditioned > 0) warn("ill_conditioned_solve", report.ill_conditioned);
    if (report.degenerate > 0) warn("degenerate_contact", report.degenerate);
    if (report.nonfinite > 0) warn("nonfinite_state", report.nonfinite);
}

bool NativeBackend::markLocalSolves(const std::vector<std::uint8_t>& due_root, std::uint8_t tick_came, double t,
                                   bool off_grid) {
    // A protection tick comes for the bodies of a pair that could close too far before the grid
    // tick: the rest of a pile has no reason to be solved again. Off the grid, an island due only
    // because ticks came (no new contact) solves the bodies within native.protection_ring touching
    // steps of those whose tick came; the next ring enters as ground moving at its drift velocity,
    // and keeps its drift (docs/native-dynamics.md, "Local protection solves").
    IslandScratch& sc = island_scratch_;
    // Cleared only after a step that marked something (the default, -1, never does: no per-step cost).
    if (sc.ring.size() != bodies_.size() || sc.local_marked) {
        sc.ring.assign(bodies_.size(), -1);
        sc.held_ground.assign(bodies_.size(), 0);
        sc.local_root.assign(bodies_.size(), 0);
        sc.local_marked = false;
    }
    const int reach = settings_.protection_ring;
    if (!off_grid || reach < 0) return false;
    const double tick = frame_dt_ / static_cast<double>(settings_.contact_substeps);
    const double quiet_speed = scene_.gravity.norm() * tick;
    std::vector<int>& queue = sc.ring_queue;
    queue.clear();
    for (int p : touching_) {
        const PairState& ps = pairs_[static_cast<std::size_t>(p)];
        for (int body : {ps.a, ps.b}) {
            const auto b = static_cast<std::size_t>(body);
            if (infinite_mass_[b] || tick_end_[b] > t || sc.ring[b] >= 0) continue;
            const auto root = static_cast<std::size_t>(islands_.islandOf(body));
            if (due_root[root] != tick_came) continue;
            sc.local_root[root] = 1;
            sc.ring[b] = 0;
            queue.push_back(body);
        }
    }
    for (std::size_t head = 0; head < queue.size(); ++head) {
        const int body = queue[head];
        for (int p : body_pairs_[static_cast<std::size_t>(body)]) {
            const PairState& ps = pairs_[static_cast<std::size_t>(p)];
            if (!ps.touching) continue;
            const int other = ps.a == body ? ps.b : ps.a;
            const auto o = static_cast<std::size_t>(other);
            if (infinite_mass_[o] || sc.ring[o] >= 0) continue;
            // Only a quiet body is held (moving slower than gravity makes it in a tick): one in
            // motion carries momentum the local solve must pass on (a ball's blow running along a
            // row of boxes, trapped between held neighbours, squeezed them into each other), so it
            // joins the solve and the search goes on past it.
            const RigidBody& rb = bodies_[o];
            const bool quiet = rb.velocity.norm() + rb.angularVelocity().norm() * shapes_[o].outer_radius <= quiet_speed;
            sc.ring[o] = std::min(sc.ring[static_cast<std::size_t>(body)] + 1, quiet ? reach + 1 : reach);
            if (sc.ring[o] > reach)
                sc.held_ground[o] = 1;
            else
                queue.push_back(other);
        }
    }
    sc.local_marked = !queue.empty();
    return sc.local_marked;
}

void NativeBackend::collisionPhase(std::vector<RigidBody>& bodies, std::vector<ContactManifold>& manifolds,
                                   const std::vector<std::uint8_t>& resting, double resting_speed, double tick,
                                   CollisionPhaseReport& report, int workers, ImpulseWaves& waves) const {
    report.ill_conditioned = report.degenerate = report.nonfinite = 0;
    report.impulsed.assign(bodies.size(), 0);
    report.settled.assign(manifolds.size(), CollisionPhaseReport::kUnsettled);
    // One manifold's impulse, its troubles counted in `tally`; true if it applied one.
    auto collideOne = [&](std::size_t k, CollisionTally& tally) {
        ContactManifold& m = manifolds[k];
        RigidBody& a = bodies[static_cast<std::size_t>(m.body_a)];
        RigidBody& b = bodies[static_cast<std::size_t>(m.body_b)];
        if (settings_.response == ResponseModel::NewtonCoulomb)
            return manifoldCollision(a, b, m, resting[k] != 0, resting_speed, tick, report.impulsed, tally);
        if (!(m.distance < scene_.collision_distance)) return false;   // speculative: not the 1995 model's
        const Vec3 u = b.pointVelocity(m.centroid) - a.pointVelocity(m.centroid);
        const double un = u.dot(m.normal);
        if (!(un < 0.0)) return false;
        // A resting contact's slow approach is stopped plastically (no micro-bounce); it must
        // still be stopped now: the contact phase only fixes the end of the step. (Leaving it to
        // the contact phase's block solve when the gap outlasts the tick holds pyramids a little
        // stiller but lets tumbling boxes in bins dig in: 1.6-1.9x the penetration_recovered.)
        const bool plastic = -un < settings_.restitution_threshold || (resting[k] != 0 && -un <= resting_speed);
        const double e = plastic ? 0.0 : m.restitution;
        const ImpulseResult r =
            settings_.response == ResponseModel::Vroc1995
                ? vroc1995Impulse(a, b, m.centroid, m.normal, e)
                : newtonCoulombImpulse(a, b, m.centroid, m.normal, e, m.friction);
        if (!applyPointImpulse(r, m.centroid, a, b, m, report.impulsed, tally)) return false;
        tally.fastest = std::max(tally.fastest, -un);
        return true;
    };
    // What a manifold does depends on its two bodies and itself alone, so one that applied nothing
    // is passed over until an impulse elsewhere changes one of its bodies: the same bits, fewer
    // visits (a pile's later sweeps change a few bodies). A wave's manifolds share no movable body,
    // so a team's workers read only counts their own manifold or an earlier wave wrote.
    auto collide = [&](std::size_t k, CollisionTally& tally) {
        ContactManifold& m = manifolds[k];
        const auto ia = static_cast<std::size_t>(m.body_a), ib = static_cast<std::size_t>(m.body_b);
        const std::uint64_t counts = (std::uint64_t{report.impulsed[ia]} << 32) | report.impulsed[ib];
        if (report.settled[k] == counts) return false;
        const bool applied = collideOne(k, tally);
        report.settled[k] = applied ? CollisionPhaseReport::kUnsettled : counts;
        return applied;
    };
    auto addTally = [&report](const CollisionTally& t) {
        report.ill_conditioned += t.ill_conditioned;
        report.degenerate += t.degenerate;
        report.nonfinite += t.nonfinite;
    };
    // Sweeps until one applies no impulse: collision_iterations at most, more (up to
    // collisionBlowIterations) while a sweep's fastest impulse met a blow, an approach faster than
    // gravity adds in a tick. On fixed ticks also faster than closes the collision distance within
    // the tick: a slower approach the contact phase stops within the window (in a mixed pile, three
    // in four blow sweeps went to approaches below that and applied nothing). Whether another sweep
    // follows one whose fastest impulse met `fastest`:
    const int sweeps = settings_.collision_iterations;
    const int hard = settings_.collisionBlowIterations();
    const double blow =
        fixedTicks(settings_.touching) ? std::max(resting_speed, scene_.collision_distance / tick) : resting_speed;
    auto again = [&](int sweep, double fastest) {
        return fastest > 0.0 && (sweep + 1 < sweeps || (sweep + 1 < hard && fastest > blow));
    };
    if (workers <= 1 || workers > kMaxCollisionTeam || manifolds.size() < kTeamManifolds) {
        CollisionTally tally;
        for (int sweep = 0; sweep < hard; ++sweep) {
            tally.fastest = 0.0;
            bool any = false;
            for (std::size_t k = 0; k < manifolds.size(); ++k) any = collide(k, tally) || any;
            if (!any || !again(sweep, tally.fastest)) break;
        }
        addTally(tally);
        return;
    }
    // A team: each wave's manifolds share no movable body, so the workers take contiguous shares
    // of it and meet after it; every dependent pair keeps the one-worker order (impulse_waves.h).
    scheduleImpulseWaves(manifolds, bodies, waves);
    std::array<CollisionTally, kMaxCollisionTeam> tallies{};
    // The fastest approach a worker's impulses met (0: it applied none), per sweep parity: a worker
    // clears its value for sweep s only after every worker has read those of sweep s - 2 (a wave's
    // barrier lies between). Their largest decides the next sweep, the same for any worker count.
    std::array<std::array<double, kMaxCollisionTeam>, 2> applied{};
    SpinBarrier barrier(workers);
    const auto team = static_cast<std::size_t>(workers);
    auto share = [&](std::size_t w) {
        CollisionTally& tally = tallies[w];
        for (int sweep = 0; sweep < hard; ++sweep) {
            double& mine = applied[static_cast<std::size_t>(sweep % 2)][w];
            mine = 0.0;
            for (std::size_t wave = 0; wave < waves.waves(); ++wave) {
                const std::size_t begin = waves.begin[wave], size = waves.begin[wave + 1] - begin;
                for (std::size_t i = begin + size * w / team; i < begin + size * (w + 1) / team; ++i) {
                    tally.fastest = 0.0;
                    if (collide(static_cast<std::size_t>(waves.order[i]), tally)) mine = std::max(mine, tally.fastest);
                }
                barrier.arriveAndWait();
            }
            const auto& flags = applied[static_cast<std::size_t>(sweep % 2)];
            if (!again(sweep, *std::max_element(flags.begin(), flags.begin() + workers))) break;
        }
    };
    // One reference captured: std::function stores it in place (no allocation per solve).
    partition_->run(team, [&share](std::size_t w, int) { share(w); });
    for (std::size_t w = 0; w < team; ++w) addTally(tallies[w]);
}

bool NativeBackend::meetsNow(const ContactManifold& m, std::size_t i, double approach, double tick, double cd) {
    // Touching (within the collision distance), or a speculative point that reaches the speculative
    // target (half the collision distance) within the tick at its approach speed.
    return !(i < m.point_gap.size() && !(m.point_gap[i] < cd) && !(approach * tick >= m.point_gap[i] - 0.5 * cd));
}

bool NativeBackend::manifoldCollision(RigidBody& a, RigidBody& b, ContactManifold& m, bool resting, double resting_speed,
                                   double tick, std::vector<std::uint32_t>& impulsed, CollisionTally& tally) const {
    // The points that touch now, and the speculative ones that reach the speculative target within
    // the tick at their approach speed: their impact is met now, up to a/|u| early (a the gap to
    // close), rather than leaving the contact phase to stop them (the drift moves a body with the
    // mean of its start and end velocities, so a fast point stopped at the tick's end still sinks
    // by |u| h / 2). Two or more make a patch.
    const double cd = scene_.collision_distance;
    const Vec3 wa = a.angularVelocity(), wb = b.angularVelocity();
    auto approach = [&](const Vec3& p) { return approachAt(a, wa, b, wb, p, m.normal); };
    // Every manifold passes here at every collision sweep: its points in place, as the manifold's.
    PointArray<Vec3> selected;
    PointArray<double> selected_restitution;
    double fastest = 0.0;   // [m/s] largest approach speed of a selected point
    for (std::size_t i = 0; i < m.points.size(); ++i) {
        const double in = approach(m.points[i]);
        if (!meetsNow(m, i, in, tick, cd)) continue;
        const bool plastic = in < settings_.restitution_threshold || (resting && in <= resting_speed);
        selected.push_back(m.points[i]);
        selected_restitution.push_back(plastic ? 0.0 : m.restitution);
        fastest = std::max(fastest, in);
    }
    if (selected.empty() || !(fastest > 0.0)) return false;
    // A resting patch whose approach is far below what gravity adds in a tick is the last solve's
    // rounding: the contact phase holds it at the tick's end (an impulse here would only re-solve
    // what that solve left).
    if (resting && fastest <= kQuietApproach * resting_speed) return false;
    // A resting patch (held by the last solve) approaching slower than gravity closes in a tick is
    // stopped plastically at its touching centroid, one impulse as in issue 9 (a pile's patches,
    // every tick); a faster one (an impact, a rocking plate) is resolved over its points.
    if (resting && fastest <= resting_speed) {
        selected.assign(1, m.centroid);
        selected_restitution.assign(1, 0.0);
        if (!(approach(m.centroid) > 0.0)) return false;
    }
    const std::span<const Vec3> points(selected.data(), selected.size());
    const std::span<const double> restitution(selected_restitution.data(), selected_restitution.size());
    if (points.size() == 1) {   // one point: the coupled sticking / sliding impulse there
        const ImpulseResult r = newtonCoulombImpulse(a, b, points[0], m.normal, restitution[0], m.friction);
        if (!applyPointImpulse(r, points[0], a, b, m, impulsed, tally)) return false;
        tally.fastest = std::max(tally.fastest, fastest);
        return true;
    }
    const PatchImpulse imp = patchImpulse(a, b, points, m.centroid, m.normal, restitution, m.friction);
    if (imp.trouble == ImpulseTrouble::IllConditioned) ++tally.ill_conditioned;
    bool finite = imp.tangent.allFinite();
    for (double x : imp.normal) finite = finite && std::isfinite(x);
    if (!finite) {
        ++tally.nonfinite;
        return false;
    }
    if (!imp.any()) return false;
    tally.fastest = std::max(tally.fastest, fastest);
    applyPatchImpulse(a, b, points, m.normal, imp);
    for (RigidBody* body : {&a, &b})
        if (!body->infiniteMass()) ++impulsed[static_cast<std::size_t>(body == &a ? m.body_a : m.body_b)];
    for (double x : imp.normal) m.collision_impulse += x;
    return true;
}

void NativeBackend::emitEvents(const std::vector<PairSample>& samples, double t) {
    // One event per pair that starts touching with a positive impulse: at its strongest manifold.
    // Fixed ticks meet an impact before touching (a speculative point reaching within the tick):
    // it is reported at the time the pair would have touched at its approach speed.
    const bool fixed = fixedTicks(settings_.touching);
    for (const PairSample& s : samples) {
        if (s.manifolds.empty()) continue;
        PairState& ps = pairs_[static_cast<std::size_t>(s.pair)];
        if (ps.in_contact || ps.impact_reported) continue;   // continuing, or met early and reported
        const bool early = fixed && !(s.distance < scene_.collision_distance);
        if (early && !(s.approach > 0.0)) continue;   // not yet
        if (!early && !(s.distance < scene_.collision_distance)) continue;
        double sum = 0.0, collision = 0.0;
        const ContactManifold* best = nullptr;
        for (const ContactManifold& m : s.manifolds) {
            const double j = m.collision_impulse + m.contact_impulse;
            if (best == nullptr || j > best->collision_impulse + best->contact_impulse) best = &m;
            sum += j;
            collision += m.collision_impulse;
        }
        if (!(sum > 0.0) || (early && !(collision > 0.0))) continue;
        CollisionEvent e;
        e.time = fixed && s.approach > 0.0 ? std::min(t + std::max(0.0, s.distance) / s.approach, frame_end_) : t;
        e.body_a = ps.a;
        e.body_b = ps.b;
        e.point = best->centroid;
        e.normal = best->normal;
        e.impulse = sum;
        events_.push_back(e);
        ++stats_.collisions;
        ps.impact_reported = early;   // until the pair parts beyond its reach (markSampled)
    }
}

double NativeBackend::fastestApproach(const PairSample& s) const {
    double fastest = 0.0;
    for (const ContactManifold& m : s.manifolds) {
        const RigidBody& a = bodies_[static_cast<std::size_t>(m.body_a)];
        const RigidBody& b = bodies_[static_cast<std::size_t>(m.body_b)];
        const Vec3 wa = a.angularVelocity(), wb = b.angularVelocity();
        for (const Vec3& p : m.points) fastest = std::max(fastest, approachAt(a, wa, b, wb, p, m.normal));
    }
    return fastest;
}

void NativeBackend::noteApproach(std::vector<PairSample>& samples) const {
    // Only a pair that may report an impact (not in contact) or has one reported reads it.
    for (PairSample& s : samples) {
        const PairState& ps = pairs_[static_cast<std::size_t>(s.pair)];
        s.approach = ps.in_contact && !ps.impact_reported ? 0.0 : fastestApproach(s);
    }
}

void NativeBackend::separatePenetrating(const PairSample& s) {
    // Emergency only: the contact phase's position pass repairs shallow penetration. Move the
    // bodies apart along the normal (by inverse mass) to half the collision distance.
    const PairState& ps = pairs_[static_cast<std::size_t>(s.pair)];
    RigidBody& a = bodies_[static_cast<std::size_t>(ps.a)];
    RigidBody& b = bodies_[static_cast<std::size_t>(ps.b)];
    const double w = a.inv_mass + b.inv_mass;
    if (!(w > 0.0) || !s.normal.allFinite()) return;
    warn("penetration_recovered");
    const double push = 0.5 * scene_.collision_distance - s.distance;
    a.com -= (a.inv_mass / w) * push * s.normal;
    b.com += (b.inv_mass / w) * push * s.normal;
    box_dirty_[static_cast<std::size_t>(ps.a)] = 1;
    box_dirty_[static_cast<std::size_t>(ps.b)] = 1;
    // The moved bodies' distance bounds (fixed ticks' pair bounds) no longer hold: each of their
    // pairs is queried at its next sample, not skipped on the old bound.
    for (int body : {ps.a, ps.b})
        for (int p : body_pairs_[static_cast<std::size_t>(body)]) pairs_[static_cast<std::size_t>(p)].gap_step = -1;
}

}  // namespace vroc::native
