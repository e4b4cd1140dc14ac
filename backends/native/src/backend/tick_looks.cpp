// SPDX-License-Identifier: MIT
// Looks inside a fixed tick (native.max_tick_looks): a pair that may close farther before the tick
// ends than its speculative patch reaches (a ball thrown at a thin wall, a hull an impact set
// spinning) is looked at again inside the tick, each time it could first have closed to the
// collision distance (conservative advancement on a closing-speed bound), with the collision phase
// there, or, where a pair in flight meets, its islands solved from there to the tick's end; and a
// lone body's impact deferred to its touching time (deferImpacts) is looked at then
// (docs/native-dynamics.md, "Looks inside a tick", "Impacts at touching on fixed ticks").
#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>

#include "backend/native_backend.h"
#include "scheduling/collision_time_bound.h"

namespace vroc::native {

void NativeBackend::lookInsideTick(double t) {
    // The tick was chosen at the frame's start from the velocities then, and a pair's patch reaches
    // only so far: a ball thrown at a thin wall, or an impact since (a heavy body landing on a light
    // hull at the edge it rests on sets it spinning at 90 rad/s), may leave a pair able to close
    // within the tick by more than its speculative patch reaches. Such a pair is looked at again
    // inside the tick, each time it could have closed to the collision distance or by its reach
    // (conservative advancement on the closing-speed bound), with the collision phase and its impact
    // passes there; the rest of the world drifts on.
    if (settings_.max_tick_looks <= 0) return;
    using Look = std::pair<double, int>;   // (time, pair): earliest first, then by pair
    std::vector<Look>& looks = step_looks_;
    looks.clear();
    const auto later = std::greater<Look>();
    // A pair's looks are counted, and its look time kept, per tick.
    auto thisTick = [&](PairState& ps) {
        if (ps.looks_step == step_index_) return;
        ps.looks_step = step_index_;
        ps.looks = 0;
        ps.look_at = kNever;
    };
    auto lookAt = [&](PairState& ps, int p, double at) {
        ps.look_at = at;
        looks.push_back({at, p});
        std::push_heap(looks.begin(), looks.end(), later);
    };
    auto schedule = [&](int p, double from) {
        PairState& ps = pairs_[static_cast<std::size_t>(p)];
        ps.look_at = kNever;
        const double next = nextLook(ps, from);
        if (!(next < frame_end_)) return;
        thisTick(ps);
        if (ps.looks >= settings_.max_tick_looks) {
            ++stats_.fixed_looks_cut;
            return;
        }
        lookAt(ps, p, next);
    };
    // At t every candidate's distance (or the bound on it) is known from the tick's sampling. A pair
    // whose points cannot outrun its reach however they move (each body's fastest point: its COM
    // speed and its turn at its outer radius) is passed over before its finer bound is worked out.
    const double h = frame_end_ - t, fall = scene_.gravity.norm() * h;
    std::vector<double>& fastest = step_point_speed_;
    fastest.resize(bodies_.size());
    for (std::size_t i = 0; i < bodies_.size(); ++i)
        fastest[i] = bodies_[i].velocity.norm() + bodies_[i].maxAngularSpeed() * shapes_[i].outer_radius;
    for (int p : candidates_) {
        const PairState& ps = pairs_[static_cast<std::size_t>(p)];
        if (ps.gap_step != step_index_) continue;
        const auto a = static_cast<std::size_t>(ps.a), b = static_cast<std::size_t>(ps.b);
        const double most = (fastest[a] + fastest[b] + (infinite_mass_[a] != infinite_mass_[b] ? fall : 0.0)) * h;
        if (!(most > settings_.speculativeReach() * smallerInnerRadius(ps, true))) continue;
        schedule(p, t);
    }
    // A lone body's impact deferred to its touching time (deferImpacts) is looked at then.
    for (const auto& [at, p] : step_deferred_) {
        PairState& ps = pairs_[static_cast<std::size_t>(p)];
        thisTick(ps);
        if (at < ps.look_at) lookAt(ps, p, at);
    }
    step_deferred_.clear();
    if (looks.empty()) return;
    ++stats_.fixed_looked_ticks;
    std::vector<int>& one = step_look_pair_;
    std::vector<int>& moved = step_kicked_;
    std::vector<PairSample>& samples = step_resampled_;
    inside_tick_ = true;
    while (!looks.empty()) {
        std::pop_heap(looks.begin(), looks.end(), later);
        const auto [at, p] = looks.back();
        looks.pop_back();
        PairState& ps = pairs_[static_cast<std::size_t>(p)];
        if (ps.look_at != at || !ps.in_broad_phase) continue;   // looked at again since, or gone
        ++stats_.fixed_tick_looks;
        ++ps.looks;
        one.assign(1, p);
        samplePairs(one, at, samples);
        moved.clear();
        island_scratch_.kicked.clear();
        if (!ps.touching && impacting(samples.front(), at)) {
            // A pair in flight meets here: its impact is solved with the islands it joins, from here
            // to the tick's end (collision and contact phases), as a tick would; a ball landing on a
            // plate on the floor is one blow through both.
            lookIslandSolve(samples, at, moved);
        } else {
            recordSamples(samples);
            impactPass(samples, at);
            markSampled(samples.front());
            recycleSamples(samples);
        }
        impactPasses(at, &moved);
        schedule(p, at);
        // A body the impact changed: each of its pairs was sampled at `at`, at the new velocities;
        // each is looked at again from there.
        std::sort(moved.begin(), moved.end());
        moved.erase(std::unique(moved.begin(), moved.end()), moved.end());
        for (int body : moved)
            for (int q : body_pairs_[static_cast<std::size_t>(body)])
                if (q != p) schedule(q, at);
    }
    inside_tick_ = false;
}

bool NativeBackend::impacting(const PairSample& s, double t) const {
    // A point of a manifold that touches, or reaches the speculative target before the tick ends at
    // its approach speed, approaching faster than gravity adds in a tick (manifoldCollision's
    // selection).
    const double cd = scene_.collision_distance, rest = frame_end_ - t;
    const double quiet = scene_.gravity.norm() * frame_dt_;
    for (const ContactManifold& m : s.manifolds) {
        const RigidBody& a = bodies_[static_cast<std::size_t>(m.body_a)];
        const RigidBody& b = bodies_[static_cast<std::size_t>(m.body_b)];
        const Vec3 wa = a.angularVelocity(), wb = b.angularVelocity();
        for (std::size_t i = 0; i < m.points.size(); ++i) {
            const double in = approachAt(a, wa, b, wb, m.points[i], m.normal);
            if (meetsNow(m, i, in, rest, cd) && in > quiet) return true;
        }
    }
    return false;
}

void NativeBackend::lookIslandSolve(std::vector<PairSample>& samples, double t, std::vector<int>& moved) {
    // The islands the pair joins: its bodies and every body touching them, through touching pairs,
    // each pair sampled here (the islands' solve takes the manifolds it is given).
    std::vector<int>& bodies = step_look_bodies_;
    std::vector<int>& pairs = step_look_pairs_;
    bodies.clear();
    pairs.clear();
    const int look = samples.front().pair;
    look_mark_.resize(bodies_.size(), 0);
    auto visit = [&](int body) {
        if (infinite_mass_[static_cast<std::size_t>(body)] || look_mark_[static_cast<std::size_t>(body)] != 0) return;
        look_mark_[static_cast<std::size_t>(body)] = 1;
        bodies.push_back(body);
    };
    for (int body : {pairs_[static_cast<std::size_t>(look)].a, pairs_[static_cast<std::size_t>(look)].b}) visit(body);
    for (std::size_t k = 0; k < bodies.size(); ++k)
        for (int q : body_pairs_[static_cast<std::size_t>(bodies[k])]) {
            const PairState& qs = pairs_[static_cast<std::size_t>(q)];
            if (!qs.touching) continue;
            pairs.push_back(q);
            visit(qs.a);
            visit(qs.b);
        }
    for (int body : bodies) look_mark_[static_cast<std::size_t>(body)] = 0;
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    std::vector<PairSample>& extra = step_extra_;
    samplePairs(pairs, t, extra);
    samples.insert(samples.end(), std::make_move_iterator(extra.begin()), std::make_move_iterator(extra.end()));
    std::sort(samples.begin(), samples.end(), [](const PairSample& x, const PairSample& y) { return x.pair < y.pair; });
    ++stats_.fixed_look_solves;
    solveIslands(samples, t);
    recycleSamples(samples);
    moved.insert(moved.end(), bodies.begin(), bodies.end());
}

double NativeBackend::pointSpeedBound(const PairState& ps, double rest) const {
    // B's material point at x moves relative to A's at x with (v_b - v_a) + w_b x (c_a - c_b) +
    // (w_b - w_a) x (x - c_a): within A's outer radius R_a of A's centre, at most the length of the
    // first two terms plus |w_b - w_a| R_a; the same about B's centre; the smaller of the two. Two
    // dominoes turning together, or a box against the drum wall it rides on, close far slower than
    // each turns. Over the `rest` [s] of the tick the bound grows to first order: torque-free
    // precession turns w by at most w_max^2 per second (a body whose moments differ; w_max =
    // |L| / smallest moment), the centres part at the relative COM speed, and against ground
    // gravity adds g per second.
    const RigidBody& a = bodies_[static_cast<std::size_t>(ps.a)];
    const RigidBody& b = bodies_[static_cast<std::size_t>(ps.b)];
    const Vec3 wa = a.angularVelocity(), wb = b.angularVelocity();
    const Vec3 dv = b.velocity - a.velocity, apart = b.com - a.com;
    const double ra = shapes_[static_cast<std::size_t>(ps.a)].outer_radius;
    const double rb = shapes_[static_cast<std::size_t>(ps.b)].outer_radius;
    const double pa = a.isotropic ? 0.0 : a.maxAngularSpeed() * a.maxAngularSpeed();
    const double pb = b.isotropic ? 0.0 : b.maxAngularSpeed() * b.maxAngularSpeed();
    const double spin = (wb - wa).norm();
    const double about_a = (dv - wb.cross(apart)).norm() + spin * ra +
                           rest * ((pa + pb) * ra + pb * apart.norm() + wb.norm() * dv.norm());
    const double about_b = (-dv + wa.cross(apart)).norm() + spin * rb +
                           rest * ((pa + pb) * rb + pa * apart.norm() + wa.norm() * dv.norm());
    const bool one_ground = infinite_mass_[static_cast<std::size_t>(ps.a)] != infinite_mass_[static_cast<std::size_t>(ps.b)];
    return std::min(about_a, about_b) + (one_ground ? scene_.gravity.norm() * rest : 0.0);
}

double NativeBackend::nextLook(const PairState& ps, double from) const {
    // The pair's distance at `from` (sampled there, or its bound at the tick's start) closes at
    // most at the closing-speed bound: it cannot reach the collision distance before the time
    // returned, nor close by more than its patch reaches (the cap) between two looks.
    const double cap = settings_.speculativeReach() * smallerInnerRadius(ps, true);
    if (!(cap > 0.0) || !(cap < kNever)) return kNever;   // two bodies that cannot move
    const double rest = frame_end_ - from;
    // Either bound holds: every point's own speed, or the material points' relative motion.
    const double speed = std::min(closingSpeed(ps, rest), pointSpeedBound(ps, rest));
    if (!(speed * rest > cap)) return kNever;   // within its reach to the tick's end
    const double gap = std::isfinite(ps.gap_bound) ? ps.gap_bound : 0.0;
    return from + std::max(cap, gap - scene_.collision_distance) / speed;
}

}  // namespace vroc::native
