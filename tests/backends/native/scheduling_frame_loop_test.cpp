// SPDX-License-Identifier: MIT
// The scheduling pieces composed into the frame loop they are built for (docs/native-scheduling.md):
// elastic spheres in a closed box, some at 100 m/s. Per frame: swept boxes -> sweep and prune ->
// queue keyed by earliestCollisionTime -> pop -> conservative advancement -> impulse -> re-key.
// Checked exactly afterwards: between any two events all motion is linear, so every pair's
// minimum distance over every interval has a closed form; none may fall below tol/2.
#include <gtest/gtest.h>

#include <cstring>
#include <map>
#include <random>
#include <vector>

#include "scheduling/collision_queue.h"
#include "scheduling/collision_time_bound.h"
#include "scheduling/pair_partition.h"
#include "scheduling/sweep_and_prune.h"
#include "scheduling/time_of_contact.h"

namespace vroc::native {
namespace {

constexpr double kBoxSize = 2.0;     // [m] the cube [0, 2]^3
constexpr double kTol = 1e-3;        // [m] collision distance
constexpr double kFrame = 1.0 / 60;  // [s]
constexpr double kLongHorizon = 10;  // [s] keys may lie many frames ahead

struct Segment { double t; Vec3 p, v; };   // position p at time t, velocity v from then on

struct Sim {
    // Bodies 0..5: static walls (slabs outside the cube); 6..: spheres.
    std::vector<Aabb> wall;
    std::vector<double> radius;              // spheres only (index - 6)
    std::vector<std::vector<Segment>> path;  // spheres only
    SweepAndPrune sap;
    CollisionQueue queue;
    std::vector<BodyPair> known_pairs;
    int collisions = 0, violations = 0;
    // toi_distance_queries: ToiResult::iterations summed (distance queries after each TOI's first).
    std::int64_t toi_distance_queries = 0, pair_frames = 0, touched_pair_frames = 0;
    std::vector<char> touched;

    int spheres() const { return static_cast<int>(radius.size()); }
    int bodies() const { return 6 + spheres(); }
    int pairIndex(int a, int b) const { return a * bodies() + b; }
    Vec3 position(int body, double t) const {
        const Segment& s = path[body - 6].back();
        return s.p + s.v * (t - s.t);
    }
    Vec3 velocity(int body) const { return body < 6 ? Vec3::Zero() : path[body - 6].back().v; }
    MotionBound bound(int body) const {
        if (body < 6) return MotionBound::stationary();
        const double r = radius[body - 6];
        return {velocity(body), Vec3::Zero(), 0.0, r, r};
    }
    // a < b always; a may be a wall.
    DistanceSample distance(int a, int b, double t) const {
        const Vec3 cb = position(b, t);
        const double rb = radius[b - 6];
        DistanceSample s;
        Vec3 on_a;
        double ra = 0.0;
        if (a < 6) {
            on_a = cb.cwiseMax(wall[a].lower).cwiseMin(wall[a].upper);
        } else {
            on_a = position(a, t);
            ra = radius[a - 6];
        }
        const Vec3 d = cb - on_a;
        const double len = d.norm();
        s.normal = len > 0 ? Vec3(d / len) : Vec3::UnitX();
        s.distance = len - ra - rb;
        s.point_a = on_a + ra * s.normal;
        s.point_b = cb - rb * s.normal;
        return s;
    }
    Aabb sweptBox(int body, double t, double t_end) const {
        const Vec3 c = position(body, t);
        const double r = radius[body - 6];
        // Grown by the collision distance too: a pair that ends the frame within tol of touching
        // must already be a broad-phase pair during this frame.
        return bound(body).sweptAabb({c - Vec3::Constant(r), c + Vec3::Constant(r)}, t_end - t).inflated(kTol);
    }
    // Lower bound on the pair's next contact time, from one distance query at t.
    double key(int a, int b, double t) const {
        const DistanceSample s = distance(a, b, t);
        const double closing = s.normal.dot(velocity(a) - velocity(b));
        if (s.distance <= kTol) {
            if (closing > 0) return t;   // touching and approaching: collide now
            return t + earliestCollisionTime(s.distance - 0.5 * kTol, s.normal, bound(a), bound(b), kLongHorizon);
        }
        return t + earliestCollisionTime(s.distance - 0.75 * kTol, s.normal, bound(a), bound(b), kLongHorizon);
    }
    void push(int a, int b, double time) {
        if (time < kNever) queue.push(pairIndex(a, b), a, b, time);
    }
    void collide(int a, int b, double t, const DistanceSample& s) {
        const Vec3 n = s.normal;
        const double ma = a < 6 ? 0.0 : 1.0 / std::pow(radius[a - 6], 3);   // inverse masses
        const double mb = 1.0 / std::pow(radius[b - 6], 3);
        const double closing = n.dot(velocity(a) - velocity(b));
        const double j = 2.0 * closing / (ma + mb);   // elastic: e = 1
        for (int body : {a, b}) {
            if (body < 6) continue;
            const Vec3 v = velocity(body) + (body == a ? -ma : mb) * j * n;
            path[body - 6].push_back({t, position(body, t), v});
            queue.invalidateBody(body);
        }
        ++collisions;
    }
    // The broad phase for [t, t_end]; keys every pair whose key is unknown (new, or its bodies moved).
    void refreshPairs(double t, double t_end, PairPartition& workers, const std::vector<int>& changed) {
        for (int body = 6; body < bodies(); ++body) sap.setAabb(body, sweptBox(body, t, t_end));
        sap.update();
        std::vector<BodyPair> todo;
        std::set_difference(sap.pairs().begin(), sap.pairs().end(), known_pairs.begin(), known_pairs.end(),
                            std::back_inserter(todo));
        for (const BodyPair& p : sap.pairs()) {
            const bool moved = std::find(changed.begin(), changed.end(), p.a) != changed.end() ||
                               std::find(changed.begin(), changed.end(), p.b) != changed.end();
            if (moved && !std::binary_search(todo.begin(), todo.end(), p)) todo.push_back(p);
        }
        std::sort(todo.begin(), todo.end());
        // Distance queries for the keys run round robin; pushes stay serial and ordered.
        const auto keys = workers.map<double>(todo.size(), [&](std::size_t i) { return key(todo[i].a, todo[i].b, t); });
        for (std::size_t i = 0; i < todo.size(); ++i) push(todo[i].a, todo[i].b, keys[i]);
        known_pairs = sap.pairs();
    }
    void handle(const QueueEntry& e, double t_end, PairPartition& workers) {
        const int a = e.body_a, b = e.body_b;
        const double t = e.time;
        touched[e.pair] = 1;
        const DistanceSample s = distance(a, b, t);
        if (s.distance < 0.5 * kTol - 1e-12) ++violations;
        const double closing = s.normal.dot(velocity(a) - velocity(b));
        if (s.distance <= kTol && closing > 0) {
            collide(a, b, t, s);
            refreshPairs(t, t_end, workers, {a, b});
            return;
        }
        if (s.distance <= kTol) { push(a, b, key(a, b, t)); return; }   // receding in the band
        auto f = [&](double time) { return distance(a, b, time); };
        const ToiResult r = conservativeAdvancement(f, bound(a), bound(b), t, t_end, {kTol, 200});
        toi_distance_queries += r.iterations;
        switch (r.state) {
            case ToiState::Hit:
            case ToiState::Failed: push(a, b, r.time); break;   // exact time, or the safe time
            case ToiState::Separated: push(a, b, key(a, b, t_end)); break;
            case ToiState::Overlapped: ++violations; break;
        }
    }
    void runFrame(double t0, PairPartition& workers) {
        const double t_end = t0 + kFrame;
        refreshPairs(t0, t_end, workers, {});
        touched.assign(static_cast<std::size_t>(bodies() * bodies()), 0);
        for (auto e = queue.top(); e && e->time <= t_end; e = queue.top()) handle(*queue.pop(), t_end, workers);
        pair_frames += static_cast<std::int64_t>(sap.pairs().size());
        for (const BodyPair& p : sap.pairs()) touched_pair_frames += touched[pairIndex(p.a, p.b)];
    }
};

Sim makeSim(int count, std::uint64_t seed, double fast_speed = 100.0, double slow_speed = 5.0) {
    Sim sim;
    const double w = 0.2, lo = -w, hi = kBoxSize + w;
    for (int axis = 0; axis < 3; ++axis) {
        for (int side = 0; side < 2; ++side) {
            Aabb box{Vec3::Constant(lo), Vec3::Constant(hi)};
            if (side == 0) box.upper[axis] = 0.0; else box.lower[axis] = kBoxSize;
            sim.wall.push_back(box);
            sim.sap.addBody(box, true);
        }
    }
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    while (sim.spheres() < count) {
        const double r = 0.04 + 0.06 * u(rng);
        const Vec3 c = Vec3::Constant(r + 0.01) + Vec3(u(rng), u(rng), u(rng)) * (kBoxSize - 2 * r - 0.02);
        bool free = true;
        for (int i = 0; i < sim.spheres(); ++i) {
            if ((sim.path[i][0].p - c).norm() < r + sim.radius[i] + 0.01) free = false;
        }
        if (!free) continue;
        const double speed = sim.spheres() % 10 == 0 ? fast_speed : slow_speed * u(rng);
        const Vec3 v = Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5).normalized() * speed;
        sim.radius.push_back(r);
        sim.path.push_back({{0.0, c, v}});
        sim.sap.addBody({c - Vec3::Constant(r), c + Vec3::Constant(r)}, false);
    }
    return sim;
}

// Minimum over [t0, t1] of |p + w (t − t0)|, closed form.
double minNorm(const Vec3& p, const Vec3& w, double span) {
    const double ww = w.squaredNorm();
    const double s = ww > 0 ? std::clamp(-p.dot(w) / ww, 0.0, span) : 0.0;
    return (p + w * s).norm();
}

// Exact check of the whole history: no sphere pair and no sphere–wall pair ever closer than tol/2.
double smallestGapEver(const Sim& sim, double t_final) {
    double smallest = kNever;
    auto at = [](const std::vector<Segment>& path, double t) -> const Segment& {
        auto it = std::upper_bound(path.begin(), path.end(), t, [](double x, const Segment& s) { return x < s.t; });
        return *(it - 1);
    };
    for (int i = 0; i < sim.spheres(); ++i) {
        const auto& pi = sim.path[i];
        for (std::size_t k = 0; k < pi.size(); ++k) {   // walls: distance is linear on a segment
            const double t1 = k + 1 < pi.size() ? pi[k + 1].t : t_final;
            for (double t : {pi[k].t, t1}) {
                const Vec3 c = pi[k].p + pi[k].v * (t - pi[k].t);
                const double gap = std::min(c.minCoeff(), kBoxSize - c.maxCoeff()) - sim.radius[i];
                smallest = std::min(smallest, gap);
            }
        }
        for (int j = i + 1; j < sim.spheres(); ++j) {
            std::vector<double> cuts{0.0, t_final};
            for (const auto& s : pi) cuts.push_back(s.t);
            for (const auto& s : sim.path[j]) cuts.push_back(s.t);
            std::sort(cuts.begin(), cuts.end());
            for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
                const double t0 = cuts[k], t1 = cuts[k + 1];
                if (!(t1 > t0)) continue;
                const Segment& si = at(pi, t0);
                const Segment& sj = at(sim.path[j], t0);
                const Vec3 p = (sj.p + sj.v * (t0 - sj.t)) - (si.p + si.v * (t0 - si.t));
                smallest = std::min(smallest, minNorm(p, sj.v - si.v, t1 - t0) - sim.radius[i] - sim.radius[j]);
            }
        }
    }
    return smallest;
}

TEST(SchedulingFrameLoop, ElasticSpheresInABoxNeverPassThroughAnything) {
    const int frames = 120;
    std::vector<Vec3> reference;
    for (int workers : {1, 4}) {
        Sim sim = makeSim(40, 77);
        PairPartition partition(workers);
        double energy0 = 0, energy1 = 0;
        for (int i = 0; i < sim.spheres(); ++i) energy0 += std::pow(sim.radius[i], 3) * sim.path[i][0].v.squaredNorm();
        for (int f = 0; f < frames; ++f) sim.runFrame(f * kFrame, partition);
        const double t_final = frames * kFrame;
        for (int i = 0; i < sim.spheres(); ++i) energy1 += std::pow(sim.radius[i], 3) * sim.path[i].back().v.squaredNorm();
        EXPECT_EQ(sim.violations, 0);
        EXPECT_GT(sim.collisions, 200);
        EXPECT_NEAR(energy1, energy0, 1e-9 * energy0);
        const double gap = smallestGapEver(sim, t_final);
        EXPECT_GE(gap, 0.5 * kTol - 1e-12) << "something came closer than tol/2";
        std::vector<Vec3> final_positions;
        for (int b = 6; b < sim.bodies(); ++b) final_positions.push_back(sim.position(b, t_final));
        if (reference.empty()) {
            reference = final_positions;
            std::printf("[info] %d collisions in %d frames; smallest gap %.3g m; %.1f TOI distance queries per pop;"
                        " %.1f%% of broad-phase pairs untouched per frame; %lld queue pops (%lld stale)\n",
                        sim.collisions, frames, gap,
                        static_cast<double>(sim.toi_distance_queries) / std::max<std::int64_t>(1, sim.queue.stats().pops),
                        100.0 * (1.0 - static_cast<double>(sim.touched_pair_frames) / std::max<std::int64_t>(1, sim.pair_frames)),
                        static_cast<long long>(sim.queue.stats().pops), static_cast<long long>(sim.queue.stats().stale_pops));
        } else {
            ASSERT_EQ(final_positions.size(), reference.size());
            EXPECT_EQ(std::memcmp(final_positions.data(), reference.data(), reference.size() * sizeof(Vec3)), 0)
                << "result depends on the worker count";
        }
    }
}

// A calm scene (I-COLLIDE's coherent setting): most broad-phase pairs keep a valid key beyond
// the frame and are not touched at all; the queue only wakes the ones whose time has come.
TEST(SchedulingFrameLoop, CalmSceneLeavesMostBroadPhasePairsUntouched) {
    Sim sim = makeSim(150, 78, 1.0, 1.0);
    PairPartition partition(1);
    const int frames = 120;
    for (int f = 0; f < frames; ++f) sim.runFrame(f * kFrame, partition);
    EXPECT_EQ(sim.violations, 0);
    EXPECT_GE(smallestGapEver(sim, frames * kFrame), 0.5 * kTol - 1e-12);
    const double untouched = 1.0 - static_cast<double>(sim.touched_pair_frames) / std::max<std::int64_t>(1, sim.pair_frames);
    std::printf("[info] calm: %d collisions, %.1f broad-phase pairs per frame, %.1f%% untouched per frame\n",
                sim.collisions, static_cast<double>(sim.pair_frames) / frames, 100.0 * untouched);
    EXPECT_GT(sim.collisions, 10);
    EXPECT_GT(untouched, 0.8);   // deterministic for this seed: no timing involved
}

}  // namespace
}  // namespace vroc::native
