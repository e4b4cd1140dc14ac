// SPDX-License-Identifier: MIT
// Looks inside a fixed tick (native.max_tick_looks): a pair that may close farther before the tick
// ends than its speculative patch reaches (a ball thrown at a thin wall, a hull an impact set
// spinning) is looked at again inside the tick, each time it could first have closed to the
// collision distance (conservative advancement on a closing-speed bound), with the collision phase
// there, or, where a pair in flight meets, its islands solved from there to the tick's end; so is a
// pair whose manifold points are predicted to close within the tick by more than the solve allowed
// (native.tick_look_depth: a face turning fast, a body the impact passes left in flight), when they
// would, or whose distance, predicted at the tick's end, falls so (native.tick_look_features: a
// corner no patch holds turning down); and a lone body's impact deferred to its touching time
// (deferImpacts) is looked at then (docs/native-dynamics.md, "Looks inside a tick", "Impacts at
// touching on fixed ticks", "Looks at a predicted closing", "Looks at a feature no patch holds").
#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>

#include "backend/native_backend.h"
#include "backend/part_query.h"
#include "scheduling/collision_time_bound.h"
#include "scheduling/vertex_approach_bound.h"

namespace vroc::native {
namespace {

// Second derivative of the gap between a face of `owner` (outward normal m, turning with w_o) and
// the other body's point q (a material point turning with w_q about the other's centre; for a
// sphere its centre, the radius being a constant offset), both bodies at constant velocities:
// (w_o x (w_o x m)) . (q - c_o) + 2 (w_o x m) . (q' - v_o) + m . q''. A face turning at w sweeps
// towards a point at its distance d from the owner's centre at w^2 d (a box spinning at 50 rad/s
// on a ball: 300 m/s^2, 3 mm in a 1/240 s tick).
double faceGapAcceleration(const RigidBody& owner, const Vec3& w_o, const Vec3& m, const RigidBody& other,
                           const Vec3& w_q, const Vec3& q) {
    const Vec3 rq = q - other.com;
    const Vec3 q_dot = other.velocity + w_q.cross(rq);
    const Vec3 q_ddot = w_q.cross(w_q.cross(rq));
    const Vec3 m_dot = w_o.cross(m);
    return w_o.cross(m_dot).dot(q - owner.com) + 2.0 * m_dot.dot(q_dot - owner.velocity) + m.dot(q_ddot);
}

bool singleSphere(const BodyShape& shape) { return shape.parts.size() == 1 && shape.parts[0].is_sphere; }

}  // namespace

double NativeBackend::closingLook(const PairState& ps, double from) const {
    const double depth = settings_.tick_look_depth * scene_.collision_distance;
    if (!(depth > 0.0) || !ps.touching || ps.sampled_step != step_index_) return kNever;
    const auto ia = static_cast<std::size_t>(ps.a), ib = static_cast<std::size_t>(ps.b);
    const RigidBody& a = bodies_[ia];
    const RigidBody& b = bodies_[ib];
    const double rest = frame_end_ - from;
    const Vec3 relative = tickAcceleration(ib, from) - tickAcceleration(ia, from);
    // No point can close by `depth` within the tick (each body's fastest point, its turn's pull and
    // Coriolis terms at its outer radius): nothing to predict (a resting pile).
    const double wa = a.maxAngularSpeed(), wb = b.maxAngularSpeed();
    const double ra = shapes_[ia].outer_radius, rb = shapes_[ib].outer_radius;
    const double speed = a.velocity.norm() + wa * ra + b.velocity.norm() + wb * rb;
    const double most = speed * rest + 0.5 * rest * rest *
                                           (relative.norm() + (wa * wa + wb * wb) * (ra + rb) + 2.0 * (wa + wb) * speed);
    if (!(most > depth)) return kNever;
    const Vec3 wav = a.angularVelocity(), wbv = b.angularVelocity();
    const bool sphere_a = singleSphere(shapes_[ia]), sphere_b = singleSphere(shapes_[ib]);
    double first = kNever;
    for (const ContactManifold& m : ps.spare_manifolds) {
        const Vec3& n = m.normal;   // from A to B
        const double pull = n.dot(relative);
        for (std::size_t i = 0; i < m.points.size(); ++i) {
            const Vec3& p = m.points[i];
            // Which body's face holds the point is not kept: the faster closing of the two (a sphere
            // has no face; two spheres close as their centres do).
            double turn = kNever;
            if (!sphere_b) turn = std::min(turn, faceGapAcceleration(b, wbv, -n, a, wav, sphere_a ? a.com : p));
            if (!sphere_a) turn = std::min(turn, faceGapAcceleration(a, wav, n, b, wbv, sphere_b ? b.com : p));
            if (!(turn < kNever)) turn = 0.0;
            const double gap = i < m.point_gap.size() ? m.point_gap[i] : m.distance;
            // It falls to min(gap - depth, 0): by `depth` below its gap, or from a gap to touching.
            const double drop = gap - std::min(gap - depth, 0.0);
            const double tau = firstReach(drop, approachAt(a, wav, b, wbv, p, n), -(turn + pull));
            if (tau <= rest) first = std::min(first, tau);
        }
    }
    if (first < kNever) return from + first;
    // A feature no manifold holds: a tumbling box whose edge contact turns into another face's
    // sinks a corner or an edge that was in no patch (the 100-box bin: 1.07 mm below the other box
    // within one tick). The pair's distance is predicted at the tick's end; if it falls below the
    // level the points are held to (closing by `depth` below the pair's gap, or from a gap to
    // touching), the pair is looked at when it first does (bisection, to 1/16 of the rest): its
    // sample there holds the new features. Not for a lone sphere, whose one point the above
    // predicts.
    if (!settings_.tick_look_features || sphere_a || sphere_b || ps.spare_manifolds.empty()) return kNever;
    double gap = kNever;
    for (const ContactManifold& m : ps.spare_manifolds) gap = std::min(gap, m.distance);
    const double level = std::min(gap - depth, 0.0);
    const double end = from + rest;
    if (!(predictedGap(ps, from, end) < level)) return kNever;
    double lo = from, hi = end;
    for (int k = 0; k < 4; ++k) {
        const double mid = 0.5 * (lo + hi);
        (predictedGap(ps, from, mid) < level ? hi : lo) = mid;
    }
    return hi;
}

Vec3 NativeBackend::tickAcceleration(std::size_t body, double from) const {
    if (infinite_mass_[body]) return Vec3::Zero();
    return drift_until_[body] > from && !sub_stepped_[body].active ? drift_acceleration_[body] : scene_.gravity;
}

double NativeBackend::predictedGap(const PairState& ps, double from, double at) const {
    const double h = at - from;
    const auto ia = static_cast<std::size_t>(ps.a), ib = static_cast<std::size_t>(ps.b);
    // Each body's frame at `at`: its centre at its acceleration over the tick, its turn at its
    // angular velocity now.
    auto posed = [&](std::size_t i) {
        const RigidBody& rb = bodies_[i];
        if (rb.is_static) return rb.framePose();
        const Vec3 w = rb.angularVelocity();
        const double speed = w.norm();
        Pose p;
        p.orientation = speed > 0.0 ? Quat(Eigen::AngleAxisd(speed * h, w / speed)) * rb.orientation : rb.orientation;
        p.orientation.normalize();
        const Vec3 com = rb.com + h * rb.velocity + 0.5 * h * h * tickAcceleration(i, from);
        p.position = com - p.orientation * rb.com_offset;
        return p;
    };
    const Pose fa = posed(ia), fb = posed(ib);
    const BodyShape& sa = shapes_[ia];
    const BodyShape& sb = shapes_[ib];
    double gap = kNever;
    for (std::size_t i = 0; i < sa.parts.size(); ++i) {
        const Pose pa = fa * sa.parts[i].local;
        for (std::size_t j = 0; j < sb.parts.size(); ++j) {
            const Pose pb = fb * sb.parts[j].local;
            // Part pairs whose balls stay apart cannot set the pair's distance.
            const double apart = (fb.apply(sb.parts[j].bound_center) - fa.apply(sa.parts[i].bound_center)).norm() -
                                 sa.parts[i].bound_radius - sb.parts[j].bound_radius;
            if (!(apart < gap)) continue;
            FeatureCache cache = ps.caches[i * sb.parts.size() + j];
            gap = std::min(gap, queryParts(sa.parts[i], pa, sb.parts[j], pb, cache).distance);
        }
    }
    return gap;
}

void NativeBackend::lookInsideTick(double t) {
    // The tick was chosen at the frame's start from the velocities then, and a pair's patch reaches
    // only so far: a ball thrown at a thin wall, or an impact since (a heavy body landing on a light
    // hull at the edge it rests on sets it spinning at 90 rad/s), may leave a pair able to close
    // within the tick by more than its speculative patch reaches. Such a pair is looked at again
    // inside the tick, each time it could have closed to the collision distance or by its reach
    // (conservative advancement on the closing-speed bound), with the collision phase and its impact
    // passes there; the rest of the world drifts on. So is a pair whose manifold points are
    // predicted to close within the tick by more than the solve let them (closingLook: a face
    // turning fast over them, a body the impact passes left in flight under gravity).
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
    // `closing`: the pair's closingLook from `from`, if the caller worked it out already.
    auto schedule = [&](int p, double from, double closing = -1.0) {
        PairState& ps = pairs_[static_cast<std::size_t>(p)];
        ps.look_at = kNever;
        const double next = std::min(nextLook(ps, from), closing >= 0.0 ? closing : closingLook(ps, from));
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
    // speed and its turn at its outer radius) is passed over before its finer bound is worked out,
    // unless its manifold is predicted to close within the tick.
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
        const bool far = most > settings_.speculativeReach() * smallerInnerRadius(ps, true);
        const double closing = closingLook(ps, t);
        if (!far && !(closing < frame_end_)) continue;
        schedule(p, t, closing);
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
