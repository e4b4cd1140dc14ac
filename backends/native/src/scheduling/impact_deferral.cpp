// SPDX-License-Identifier: MIT
// NativeBackend::deferImpacts (declared in backend/native_backend.h; kept here with the contact
// time refinement it drives, scheduling/contact_time_refinement.h). A pair inside the collision
// window but not touching (gap > gap_max) is not resolved at the window gap: its pair is queried
// again at the refined touching time, and the impulse is applied then, at a gap in [0, gap_max].
// Until then the pair has no manifold (no collision or contact impulse).
#include <algorithm>
#include <cmath>
#include <vector>

#include "backend/native_backend.h"
#include "scheduling/contact_time_refinement.h"

namespace vroc::native {

namespace {
// The resolved gap relative to the pair's size (issue 4: touching "within 1e-9 of scale").
constexpr double kTouchingGapPerSize = 1e-9;
// Fixed ticks: a body other than a sphere is deferred only while its turn moves its points (|ω| x
// outer radius) slower than this fraction of its approach (deferImpacts).
constexpr double kLandingSpin = 0.1;
}  // namespace

void NativeBackend::deferImpacts(std::vector<PairSample>& samples, double t, double horizon, bool fixed_tick) {
    // A body in contact with two pairs does not fly freely: its impacts are resolved as before.
    std::vector<int>& touches = island_scratch_.touches;
    touches.assign(bodies_.size(), 0);
    for (const PairSample& s : samples) {
        if (s.manifolds.empty()) continue;
        const PairState& ps = pairs_[static_cast<std::size_t>(s.pair)];
        ++touches[static_cast<std::size_t>(ps.a)];
        ++touches[static_cast<std::size_t>(ps.b)];
    }
    auto freeBody = [&](int body) {
        return bodies_[static_cast<std::size_t>(body)].infiniteMass() || touches[static_cast<std::size_t>(body)] == 1;
    };
    auto round = [&](int body) {
        const BodyShape& sh = shapes_[static_cast<std::size_t>(body)];
        return sh.parts.size() == 1 && sh.parts[0].is_sphere;
    };
    // Event-driven: only a single sphere against a real (static) body for now: after an impact at
    // ~0 gap, a touching pair's protection bound (scheduleSampled) still lets it close by 1/8 of the
    // collision distance, so a hull whose bounce spins another vertex down would penetrate
    // (NativeRest.DroppedHullComesToRestWithinCollisionDistance). A sphere on a static body has a
    // single contact point that the bounce moves straight away.
    // Fixed ticks have no protection bound: any dynamic body against a static or tracked one, alone
    // in the broad phase with such bodies (no blow inside the tick moves it before its touching
    // time), approaching at its touching time faster than gravity adds in the tick (slower, it is
    // settling: the contact phase's), and, unless a sphere, turning slowly (a tumbling hull brings
    // more of itself down after its first feature's bounce; the tick's speculative patch meets
    // those at once, while a flat box lands on its four corners at once, at its touching time).
    auto alone = [&](int body) {
        for (int p : body_pairs_[static_cast<std::size_t>(body)]) {
            const PairState& q = pairs_[static_cast<std::size_t>(p)];
            if (!bodies_[static_cast<std::size_t>(q.a == body ? q.b : q.a)].infiniteMass()) return false;
        }
        return true;
    };
    // The approach at touching, as a body falling freely onto the ground closes: its approach at
    // the tick's start v, its gap d and gravity along the normal towards the ground g_n give
    // sqrt(v² + 2 g_n d). A low bounce's ball leaves the tick's start slower than gravity adds in a
    // tick and touches faster; a body resting on a floor within a 1 mm collision distance (at most
    // 0.14 m/s, against 0.16 m/s in a 60 Hz tick) is settling, and is not refined for nothing at
    // every tick; against a wall gravity adds nothing.
    const double g = scene_.gravity.norm();
    auto deferrable = [&](int body, int other, const PairSample& s) {
        const RigidBody& rb = bodies_[static_cast<std::size_t>(body)];
        const RigidBody& ground = bodies_[static_cast<std::size_t>(other)];
        if (rb.infiniteMass()) return false;
        if (!fixed_tick) return ground.is_static && round(body);
        if (!ground.infiniteMass() || !alone(body)) return false;
        const double fastest = fastestApproach(s);
        // The normal points from the pair's body a to its body b.
        const bool is_a = body == pairs_[static_cast<std::size_t>(s.pair)].a;
        const double towards = std::max(0.0, (is_a ? 1.0 : -1.0) * scene_.gravity.dot(s.normal));
        const double approach = std::sqrt(fastest * fastest + 2.0 * towards * std::max(0.0, s.distance));
        if (!(approach > g * horizon)) return false;
        return round(body) || rb.maxAngularSpeed() * shapes_[static_cast<std::size_t>(body)].outer_radius <=
                                  kLandingSpin * approach;
    };
    for (PairSample& s : samples) {
        PairState& ps = pairs_[static_cast<std::size_t>(s.pair)];
        // A pair placed within the collision distance (scenes put resting bodies there) is in
        // contact from the start, as the collision distance defines; it stays so until it leaves
        // the window (a step without a manifold, or not queried at the previous step). A pair
        // first queried later (its broad-phase boxes just met) has flown in: it is not resting.
        if (!ps.sampled_once) ps.placed_in_window = t <= 0.0 && !s.manifolds.empty();
        else if (s.manifolds.empty() || !ps.touching) ps.placed_in_window = false;
        if (s.manifolds.empty() || ps.placed_in_window) continue;
        if (!freeBody(ps.a) || !freeBody(ps.b)) continue;
        const BodyShape& sa = shapes_[static_cast<std::size_t>(ps.a)];
        const BodyShape& sb = shapes_[static_cast<std::size_t>(ps.b)];
        const double gap_max = kTouchingGapPerSize * (sa.outer_radius + sb.outer_radius);
        if (!(s.distance > gap_max)) continue;
        if (!deferrable(ps.a, ps.b, s) && !deferrable(ps.b, ps.a, s)) continue;
        // Not touching yet (gap > gap_max): the body flies freely inside the window too, rising
        // or falling, so the contact phase must not catch it there (a bounce lower than the
        // collision distance keeps its e^(2n) height). It is resolved when it touches.
        const RigidBody& a = bodies_[static_cast<std::size_t>(ps.a)];
        const RigidBody& b = bodies_[static_cast<std::size_t>(ps.b)];
        std::vector<DistanceSample> now;
        for (const PartGap& g : s.parts) now.push_back({g.distance, g.normal});
        const RefineResult r =
            refineContactTime(flightGaps(a, sa, b, sb, ps.caches, scene_.gravity, t), now, ballisticBound(ps.a),
                              ballisticBound(ps.b), t, t + horizon, gap_max);
        stats_.narrow_queries += static_cast<std::int64_t>(r.queries * sa.parts.size() * sb.parts.size());
        if (r.state == RefineState::Failed) continue;
        // Clear: no touching within this step (its horizon may be a rounding sliver of a frame):
        // the body just flies on. Otherwise its pair is due again at the refined time.
        s.contact_time = r.state == RefineState::Clear ? t + horizon : r.time;
        s.manifolds.clear();
        s.manifold_part.clear();
        s.deferred = true;
    }
}

}  // namespace vroc::native
