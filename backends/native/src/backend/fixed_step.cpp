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

int NativeBackend::fixedTicksFor(double dt) {
    const int base = std::max(1, settings_.contact_substeps);
    if (settings_.max_fixed_ticks <= base) return base;
    // Boxes swept over the whole frame: every pair that could meet within it.
    frame_end_ = time_ + dt;
    frame_dt_ = dt;
    std::vector<int>& entered = step_entered_;
    entered.clear();
    updateBroadPhase(true, entered);
    // A tick may close a pair by at most the speculative reach's cap (what its patch can hold): a
    // fast body (a ball thrown into a pile) splits the frame into more ticks, up to the limit.
    const double cap_fraction = settings_.speculativeReach();
    double ticks = base;
    for (int p : candidates_) {
        const PairState& ps = pairs_[static_cast<std::size_t>(p)];
        double size = kNever;
        for (int body : {ps.a, ps.b})
            if (!infinite_mass_[static_cast<std::size_t>(body)] && asleep_[static_cast<std::size_t>(body)] == 0)
                size = std::min(size, shapes_[static_cast<std::size_t>(body)].inner_radius);
        if (!(size < kNever) || !(cap_fraction * size > 0.0)) continue;
        const double tick = dt / static_cast<double>(base);
        ticks = std::max(ticks, std::ceil(closingSpeed(ps, tick) * dt / (cap_fraction * size)));
    }
    return static_cast<int>(std::min<double>(ticks, std::max(base, settings_.max_fixed_ticks)));
}

void NativeBackend::stepFixed(double dt) {
    const int ticks = fixedTicksFor(dt);
    const double start = time_;
    for (int k = 0; k < ticks; ++k) {
        const double t = start + dt * static_cast<double>(k) / static_cast<double>(ticks);
        const double end = k + 1 == ticks ? start + dt : start + dt * static_cast<double>(k + 1) / static_cast<double>(ticks);
        // The tick is the "frame" the broad phase sweeps boxes over and the islands are solved to.
        frame_end_ = end;
        frame_dt_ = end - t;
        fixedTick(t);
        time_ = end;
    }
    frame_end_ = start + dt;
    frame_dt_ = dt;
    time_ = frame_end_;
    ++stats_.frames;
    stats_.internal_steps += ticks;
    stats_.max_internal_steps_per_frame = std::max<std::int64_t>(stats_.max_internal_steps_per_frame, ticks);
}

void NativeBackend::fixedTick(double t) {
    ++step_index_;
    changed_.clear();   // every pair is sampled at every tick: nothing to chase
    std::vector<int>& entered = step_entered_;
    entered.clear();
    updateBroadPhase(true, entered);
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
    std::vector<int>& due = step_due_;
    due.clear();
    for (int p : candidates_) {
        const PairState& ps = pairs_[static_cast<std::size_t>(p)];
        if (awake(ps.a) || awake(ps.b) || pushes(ps.a, ps.b) || pushes(ps.b, ps.a)) due.push_back(p);
    }
    stats_.flight_pair_queries += static_cast<std::int64_t>(due.size());
    std::vector<PairSample>& samples = step_samples_;
    samplePairs(due, t, samples);
    solveIslands(samples, t);
    recycleSamples(samples);
    changed_.clear();
    for (std::size_t i = 0; i < bodies_.size(); ++i) syncBody(static_cast<int>(i), frame_end_);
}

void NativeBackend::markSampled(const PairSample& s) {
    PairState& ps = pairs_[static_cast<std::size_t>(s.pair)];
    const bool touching = !s.manifolds.empty();
    ps.touching = touching;
    ps.in_contact = touching && s.distance < scene_.collision_distance;
    ps.sampled_once = true;
    if (touching ? touching_.insert(s.pair).second : touching_.erase(s.pair) > 0) ticks_dirty_ = true;
}

}  // namespace vroc::native
