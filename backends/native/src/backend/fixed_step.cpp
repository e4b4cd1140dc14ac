// SPDX-License-Identifier: MIT
// Fixed ticks (native.touching=fixed, fixed-soft): Bullet's and Box2D's schedule inside the native
// backend. A frame is native.contact_substeps ticks; at each, every broad-phase pair (boxes swept
// over the tick) is sampled with speculative points for what it may close within the tick, and
// every island with a manifold gets its collision and contact phases over the tick. There are no
// events: no queue key, no protection tick. A body with no pair in reach flies exactly, as in the
// event-driven regimes (docs/native-dynamics.md, "Fixed ticks").
#include <algorithm>
#include <cmath>

#include "backend/native_backend.h"
#include "scheduling/collision_time_bound.h"

namespace vroc::native {
namespace {

// Passes per tick that sample again the pairs of bodies an impact set moving (fixedTick): a blow
// runs one more pair down a row per pass (a ball into a base-12 pyramid's row of eleven boxes).
constexpr int kImpactPasses = 16;
// Runs of candidate pairs a worker takes at a time when they are looked over (fixedTick).
constexpr std::size_t kPairShare = 256;

}  // namespace

int NativeBackend::fixedTicksFor(double dt, bool& swept) {
    const int base = std::max(1, settings_.contact_substeps);
    swept = false;
    if (settings_.max_fixed_ticks <= base) return base;
    // Boxes swept over the whole frame: every pair that could meet within it.
    frame_end_ = time_ + dt;
    frame_dt_ = dt;
    std::vector<int>& entered = step_entered_;
    entered.clear();
    updateBroadPhase(true, entered);
    swept = true;
    // A tick may close a pair by at most the speculative reach's cap (what its patch can hold): a
    // fast body (a ball thrown into a pile) splits the frame into more ticks, up to the limit.
    const double cap_fraction = settings_.speculativeReach();
    const double tick = dt / static_cast<double>(base);
    double ticks = base;
    for (int p : candidates_) {
        const PairState& ps = pairs_[static_cast<std::size_t>(p)];
        const double size = smallerInnerRadius(ps, true);
        if (!(size < kNever) || !(cap_fraction * size > 0.0)) continue;
        ticks = std::max(ticks, std::ceil(closingSpeed(ps, tick) * dt / (cap_fraction * size)));
    }
    return static_cast<int>(std::min<double>(ticks, std::max(base, settings_.max_fixed_ticks)));
}

void NativeBackend::stepFixed(double dt) {
    bool swept = false;
    const int ticks = fixedTicksFor(dt, swept);
    const double start = time_;
    for (int k = 0; k < ticks; ++k) {
        const double t = start + dt * static_cast<double>(k) / static_cast<double>(ticks);
        const double end = k + 1 == ticks ? start + dt : start + dt * static_cast<double>(k + 1) / static_cast<double>(ticks);
        // The tick is the "frame" the broad phase sweeps boxes over and the islands are solved to.
        frame_end_ = end;
        frame_dt_ = end - t;
        // One tick: its boxes are the frame's, swept just now by fixedTicksFor.
        fixedTick(t, swept && ticks == 1);
        time_ = end;
    }
    frame_end_ = start + dt;   // == time_: the last tick ends there
    frame_dt_ = dt;
    ++stats_.frames;
    stats_.internal_steps += ticks;
    stats_.max_internal_steps_per_frame = std::max<std::int64_t>(stats_.max_internal_steps_per_frame, ticks);
}

void NativeBackend::fixedTick(double t, bool boxes_swept) {
    ++step_index_;
    changed_.clear();   // every pair is sampled at every tick: nothing to chase
    std::vector<int>& entered = step_entered_;
    entered.clear();
    if (!boxes_swept) updateBroadPhase(true, entered);
    stats_.broad_phase_pairs += static_cast<std::int64_t>(candidates_.size());
    // A pair of two bodies that cannot move (asleep, static or tracked) needs no sample; an
    // awake body's pair with a sleeping one does (its solve wakes the sleeper's island).
    auto awake = [this](int body) {
        const auto b = static_cast<std::size_t>(body);
        return !infinite_mass_[b] && asleep_[b] == 0;
    };
    auto pushes = [this](int body, int other) {   // a tracked body against a dynamic one
        return bodies_[static_cast<std::size_t>(body)].is_kinematic && !infinite_mass_[static_cast<std::size_t>(other)];
    };
    if (settings_.pair_bounds) lowerGapBounds();
    // Each candidate's verdict on its own (the workers share them out), then the due list in
    // candidate order.
    constexpr std::uint8_t kSkip = 0, kBounded = 1, kDue = 2;
    std::vector<std::uint8_t>& verdict = step_verdict_;
    verdict.resize(candidates_.size());
    partition_->forEachShared(candidates_.size(), kPairShare, [&](std::size_t k) {
        const PairState& ps = pairs_[static_cast<std::size_t>(candidates_[k])];
        std::uint8_t v = kDue;
        if (!(awake(ps.a) || awake(ps.b) || pushes(ps.a, ps.b) || pushes(ps.b, ps.a)))
            v = kSkip;
        else if (settings_.pair_bounds && boundedApart(ps))
            v = kBounded;   // its query would find it beyond its reach: no manifold, as if sampled
        verdict[k] = v;
    });
    std::vector<int>& due = step_due_;
    due.clear();
    for (std::size_t k = 0; k < candidates_.size(); ++k) {
        if (verdict[k] == kBounded) passOverBounded(candidates_[k]);
        if (verdict[k] == kDue) due.push_back(candidates_[k]);
    }
    stats_.flight_pair_queries += static_cast<std::int64_t>(due.size());
    std::vector<PairSample>& samples = step_samples_;
    island_scratch_.kicked.clear();
    samplePairs(due, t, samples);
    solveIslands(samples, t);
    recycleSamples(samples);
    // A body an impact set moving (or stopped) may now reach a neighbour its pair was sampled too
    // far from, or one the islands' solve held at its old velocity (a row of boxes struck end on).
    impactPasses(t);
    // A pair that may still close within the tick by more than its patch reaches (a ball thrown at
    // a thin wall, a light hull a heavy one set spinning) is looked at again inside the tick.
    lookInsideTick(t);
    changed_.clear();
    syncAllBodies(frame_end_);
}

void NativeBackend::impactPasses(double t, std::vector<int>* moved) {
    // The kicked bodies' pairs are sampled again at the new velocities, and those that now reach get
    // the collision phase at t (Newton restitution and friction at their approaching points); a body
    // it changes faster than gravity does in the tick flies freely for the rest of the tick, and its
    // own pairs are looked at in the next pass. A few passes carry a blow down a row; the contact
    // phase takes the new pairs at the next tick.
    std::vector<int>& entered = step_entered_;
    for (int pass = 0; pass < kImpactPasses && !island_scratch_.kicked.empty(); ++pass) {
        std::vector<int>& kicked = island_scratch_.kicked;
        std::sort(kicked.begin(), kicked.end());
        kicked.erase(std::unique(kicked.begin(), kicked.end()), kicked.end());
        if (moved != nullptr) moved->insert(moved->end(), kicked.begin(), kicked.end());
        // Their boxes, swept again at the new velocities: a pair the tick's broad phase left out (a
        // ball bouncing up off the floor) is one again once a blow sends the ball back down.
        entered.clear();
        updateBroadPhase(false, entered);
        std::vector<int>& again = step_again_;
        again.clear();
        // A pair still beyond its reach at the new velocities (its distance at t, or the bound
        // on it, against the reach those velocities give) would be queried to no manifold, as in
        // the tick's own sampling: it is left out (in a turning drum, two pairs in three). Inside
        // the tick (a look) the bounds, taken at its start, no longer hold.
        for (int body : kicked)
            for (int p : body_pairs_[static_cast<std::size_t>(body)]) {
                if (!inside_tick_ && settings_.pair_bounds && boundedApart(pairs_[static_cast<std::size_t>(p)])) {
                    passOverBounded(p);
                    continue;
                }
                again.push_back(p);
            }
        kicked.clear();
        std::sort(again.begin(), again.end());
        again.erase(std::unique(again.begin(), again.end()), again.end());
        if (again.empty()) break;
        std::vector<PairSample>& resampled = step_resampled_;
        samplePairs(again, t, resampled);
        recordSamples(resampled);
        ++stats_.fixed_impact_passes;
        impactPass(resampled, t);
        for (const PairSample& smp : resampled) markSampled(smp);
        recycleSamples(resampled);
    }
}

void NativeBackend::impactPass(std::vector<PairSample>& samples, double t) {
    IslandScratch& sc = island_scratch_;
    IslandSolve& is = sc.impact;
    is.reset(-1);
    for (const PairSample& smp : samples)
        for (const ContactManifold& m : smp.manifolds) {
            is.bodies.push_back(m.body_a);
            is.bodies.push_back(m.body_b);
        }
    if (is.bodies.empty()) return;
    std::sort(is.bodies.begin(), is.bodies.end());
    is.bodies.erase(std::unique(is.bodies.begin(), is.bodies.end()), is.bodies.end());
    auto localOf = [&](int id) {
        return static_cast<int>(std::lower_bound(is.bodies.begin(), is.bodies.end(), id) - is.bodies.begin());
    };
    for (int id : is.bodies) is.local.push_back(bodies_[static_cast<std::size_t>(id)]);
    for (const PairSample& smp : samples)
        for (const ContactManifold& m : smp.manifolds) {
            is.solved.push_back(m);
            is.solved.back().body_a = localOf(m.body_a);
            is.solved.back().body_b = localOf(m.body_b);
            // New at the tick's start: an impact, with its restitution. Inside the tick, a pair touching
            // since its last sample whose bodies the tick's solve holds is resting: an approach
            // slower than gravity adds in a tick is the drift's, stopped plastically if at all.
            const PairState& ps = pairs_[static_cast<std::size_t>(m.pair)];
            is.resting.push_back(inside_tick_ && ps.touching && heldAt(ps.a, t) && heldAt(ps.b, t) ? 1 : 0);
        }
    noteApproach(samples);
    // Called from the tick alone (no islands in flight): every worker may share it.
    const double resting_speed = scene_.gravity.norm() * (inside_tick_ ? frame_dt_ : frame_end_ - t);
    collisionPhase(is.local, is.solved, is.resting, resting_speed, frame_end_ - t, is.collision, partition_->workers(),
                   is.waves);
    warnCollision(is.collision);
    // The impulses back on the samples' manifolds: a pair that starts touching here is an event.
    std::size_t solved = 0;
    for (PairSample& smp : samples)
        for (ContactManifold& m : smp.manifolds) {
            m.collision_impulse = is.solved[solved].collision_impulse;
            m.contact_impulse = 0.0;
            ++solved;
        }
    emitEvents(samples, t);
    for (std::size_t k = 0; k < is.bodies.size(); ++k) {
        if (is.collision.impulsed[k] == 0) continue;
        const int body = is.bodies[k];
        if (kickedFaster(bodies_[static_cast<std::size_t>(body)], is.local[k], body, frame_end_ - t))
            sc.kicked.push_back(body);
        const auto b = static_cast<std::size_t>(body);
        bodies_[b] = is.local[k];
        // A drift of constant force (the block contact phase's) takes the impulse on top: its
        // velocity at t is the drift's start, so the tick's contact force still holds the body. A
        // sub-stepped drift (the soft step's) ends at its own velocities: the body flies from t.
        if (drift_until_[b] > t && !sub_stepped_[b].active)
            bumpVersion(body);
        else
            endDrift(body);
        if (asleep_[b] != 0) wake(body);
    }
}

void NativeBackend::lowerGapBounds() {
    // How far any point of each body moved since the last tick began: its centre's displacement and,
    // for the turn between the two orientations (angle theta), 2 sin(theta / 2) x its outer radius.
    // The distance of two bodies falls by at most the sum of theirs.
    const bool first = tick_start_pose_.size() != bodies_.size();
    if (first) tick_start_pose_.resize(bodies_.size());
    std::vector<double>& moved = step_moved_;
    moved.assign(bodies_.size(), 0.0);
    // Every body, then every pair, on its own: the workers share them out.
    partition_->forEachShared(bodies_.size(), kPairShare, [&](std::size_t i) {
        const Pose now{bodies_[i].com, bodies_[i].orientation};   // every surface point within R of the COM
        if (!first) {
            const Pose& was = tick_start_pose_[i];
            const double cos_half = std::min(1.0, std::abs(was.orientation.dot(now.orientation)));
            const double sin_half = std::sqrt(std::max(0.0, 1.0 - cos_half * cos_half));
            moved[i] = (now.position - was.position).norm() + 2.0 * sin_half * shapes_[i].outer_radius;
        }
        tick_start_pose_[i] = now;
    });
    if (first) return;
    partition_->forEachShared(candidates_.size(), kPairShare, [&](std::size_t k) {
        PairState& ps = pairs_[static_cast<std::size_t>(candidates_[k])];
        // No bound from the last tick (never queried, or out of the broad phase at some tick since:
        // its bound missed that tick's motion): it stays unbounded until its next query.
        if (ps.gap_step != step_index_ - 1) return;
        ps.gap_bound -= moved[static_cast<std::size_t>(ps.a)] + moved[static_cast<std::size_t>(ps.b)];
        ps.gap_step = step_index_;
    });
}

bool NativeBackend::boundedApart(const PairState& ps) const {
    if (ps.touching || ps.gap_step != step_index_) return false;
    return ps.gap_bound >= std::max(scene_.collision_distance, patchReach(ps));
}

void NativeBackend::passOverBounded(int pair) {
    ++stats_.bounded_pairs;
    pairs_[static_cast<std::size_t>(pair)].impact_reported = false;   // beyond its reach: it has parted
}

bool NativeBackend::kickedFaster(const RigidBody& before, const RigidBody& after, int body, double tick) const {
    return changedFaster(after.velocity - before.velocity, after.angularVelocity() - before.angularVelocity(), body,
                         tick);
}

bool NativeBackend::changedFaster(const Vec3& dv, const Vec3& dw, int body, double tick) const {
    return dv.norm() + dw.norm() * shapes_[static_cast<std::size_t>(body)].outer_radius > scene_.gravity.norm() * tick;
}

void NativeBackend::markSampled(const PairSample& s) {
    PairState& ps = pairs_[static_cast<std::size_t>(s.pair)];
    const bool touching = !s.manifolds.empty();
    ps.touching = touching;
    ps.in_contact = touching && s.distance < scene_.collision_distance;
    // An impact met early stays reported until the pair touches (then it is a continuing contact),
    // parts (it is seen leaving) or leaves its reach.
    if (!touching || ps.in_contact || s.approach < 0.0) ps.impact_reported = false;
    ps.sampled_once = true;
    // Queried at this tick's start (fixed ticks sample at t), its distance bounds the pair's from the
    // next tick's start less the motion since this one's; queried inside the tick, it does not.
    ps.gap_bound = s.distance;
    ps.gap_step = inside_tick_ ? -1 : step_index_;
    if (touching ? touching_.insert(s.pair).second : touching_.erase(s.pair) > 0) ticks_dirty_ = true;
}

}  // namespace vroc::native
