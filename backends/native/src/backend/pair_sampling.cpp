// SPDX-License-Identifier: MIT
// Broad phase and narrow phase of the native step: which pairs exist (sweep and prune on swept
// boxes), their closest features (the coherent walk), their contact patches reduced to manifolds,
// and when each pair in flight must be looked at again (the collision queue's key).
#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "backend/native_backend.h"
#include "backend/part_query.h"
#include "scheduling/collision_time_bound.h"

namespace vroc::native {
namespace {

// Separation targets as fractions of the collision distance (docs/native-scheduling.md): a pair in
// flight is looked at again before it can close below 3/4 of it; a touching pair that no solve
// covers before its island is solved below 1/4 (never to 0).
constexpr double kApproachTarget = 0.75;
constexpr double kTouchingFloor = 0.25;
constexpr double kTouchingMinAllowance = 0.125;
// A pair its island's contact phase holds may close to this (a penetration of half the collision
// distance at worst, repaired by the next solve's position pass; deeper is an emergency).
constexpr double kSolvedFloor = -0.5;
// A bouncing sphere is looked at again once its gap exceeds this fraction of the pair's size (1000x
// the refinement's touching gap, so the refinement takes it).
constexpr double kRecheckGapPerSize = 1e-6;
// Shortest interval between solves of an island held by its last solve, as a fraction of its tick.
constexpr double kHeldMinTick = 1.0 / 64.0;

// Speculative regime: the longest island tick, in sub-steps (a tick after an off-grid solve ends at
// the first grid point at least half a sub-step away), and the farthest a speculative feature may
// be, as a fraction of the smaller body's inner radius, is native.speculative_reach.
constexpr double kLongestTick = 1.5;

// Fixed ticks: a penetration deeper than this fraction of the smaller body's inner radius is repaired
// by moving the bodies apart (penetration_recovered); a shallower one is left to the contact phase.
constexpr double kFixedRepairDepth = 0.5;

// How far ahead [s] a pair's earliest collision time is computed for the queue.
constexpr double kQueueHorizon = 1.0;
// Pairs below this count are sampled on the calling thread (waking the pool costs more).
constexpr std::size_t kMinParallelPairs = 8;

/// (a, b) as one number ordered as the pair: the key of pair_index_ and of the pair lists' order.
std::uint64_t pairKey(int a, int b) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

}  // namespace

NativeBackend::PairState& NativeBackend::pairState(int a, int b) {
    auto [it, inserted] = pair_index_.try_emplace(pairKey(a, b), static_cast<int>(pairs_.size()));
    if (inserted) {
        PairState ps;
        ps.a = a;
        ps.b = b;
        const std::size_t n = shapes_[static_cast<std::size_t>(a)].parts.size() * shapes_[static_cast<std::size_t>(b)].parts.size();
        ps.caches.resize(n);
        ps.manifolds.resize(n);
        ps.anchors.resize(n);
        pairs_.push_back(std::move(ps));
    }
    return pairs_[static_cast<std::size_t>(it->second)];
}

void NativeBackend::updateBroadPhase(bool all, std::vector<int>& entered) {
    // A box swept from the body's valid time to the frame end stays valid while the body keeps its
    // motion, so only bodies whose velocity or position was changed need a new one.
    bool changed = false;
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        if (!all && box_dirty_[i] == 0) continue;
        box_dirty_[i] = 0;
        if (bodies_[i].is_static) continue;
        broad_phase_.setAabb(static_cast<int>(i), sweptBox(static_cast<int>(i)));
        changed = true;
    }
    if (!changed && !all) return;
    broad_phase_.update();
    // Only what the broad phase changed is touched. candidates_ and every body's list keep the
    // broad phase's own (a, b) order, as a walk over all its pairs would give them.
    auto keyOf = [this](int idx) {
        const PairState& ps = pairs_[static_cast<std::size_t>(idx)];
        return pairKey(ps.a, ps.b);
    };
    auto insertOrdered = [&keyOf](std::vector<int>& list, int idx) {
        const std::uint64_t key = keyOf(idx);
        list.insert(std::lower_bound(list.begin(), list.end(), key, [&keyOf](int x, std::uint64_t k) { return keyOf(x) < k; }),
                    idx);
    };
    auto eraseOrdered = [&keyOf](std::vector<int>& list, int idx) {
        const std::uint64_t key = keyOf(idx);
        const auto it = std::lower_bound(list.begin(), list.end(), key, [&keyOf](int x, std::uint64_t k) { return keyOf(x) < k; });
        assert(it != list.end() && *it == idx);   // every listed pair is in its lists
        list.erase(it);
    };
    // candidates_ gets the added pairs by one merge (they come in (a, b) order) and loses the
    // removed ones by one pass: a many-pair list is walked once, not shifted once per pair.
    const std::size_t entered_before = entered.size();
    for (const BodyPair& bp : broad_phase_.added()) {
        PairState& ps = pairState(bp.a, bp.b);
        const int idx = static_cast<int>(&ps - pairs_.data());
        ps.in_broad_phase = true;
        entered.push_back(idx);
        insertOrdered(body_pairs_[static_cast<std::size_t>(bp.a)], idx);
        insertOrdered(body_pairs_[static_cast<std::size_t>(bp.b)], idx);
    }
    for (const BodyPair& bp : broad_phase_.removed()) {
        const int idx = pair_index_.at(pairKey(bp.a, bp.b));
        PairState& ps = pairs_[static_cast<std::size_t>(idx)];
        ps.in_broad_phase = false;   // its boxes parted: it cannot touch before they meet again
        ps.impact_reported = false;
        queue_.removePair(idx);
        if (ps.touching) {
            ps.touching = false;
            touching_.erase(idx);
            ticks_dirty_ = true;
        }
        for (PersistentManifold& m : ps.manifolds) m.clear();
        for (ManifoldAnchor& m : ps.anchors) m.valid = false;
        eraseOrdered(body_pairs_[static_cast<std::size_t>(bp.a)], idx);
        eraseOrdered(body_pairs_[static_cast<std::size_t>(bp.b)], idx);
    }
    if (!broad_phase_.removed().empty())
        std::erase_if(candidates_, [this](int idx) { return !pairs_[static_cast<std::size_t>(idx)].in_broad_phase; });
    if (entered.size() > entered_before) {
        std::vector<int>& merged = candidates_merge_;
        merged.clear();
        std::merge(candidates_.begin(), candidates_.end(), entered.begin() + static_cast<std::ptrdiff_t>(entered_before), entered.end(),
                   std::back_inserter(merged), [&keyOf](int x, int y) { return keyOf(x) < keyOf(y); });
        candidates_.swap(merged);
    }
}

NativeBackend::PairSample NativeBackend::samplePair(int pair_index) {
    PairState& ps = pairs_[static_cast<std::size_t>(pair_index)];
    PairSample out;
    out.pair = pair_index;
    out.distance = std::numeric_limits<double>::infinity();
    const BodyShape& sa = shapes_[static_cast<std::size_t>(ps.a)];
    const BodyShape& sb = shapes_[static_cast<std::size_t>(ps.b)];
    const Pose fa = bodies_[static_cast<std::size_t>(ps.a)].framePose();
    const Pose fb = bodies_[static_cast<std::size_t>(ps.b)].framePose();
    const ContactMaterial mat = combineMaterials(scene_.materials[scene_.bodies[ps.a].material],
                                                 scene_.materials[scene_.bodies[ps.b].material]);
    const double cd = scene_.collision_distance;
    const double reach = patchReach(ps);
    out.reach = reach;
    // The storage of the pair's previous sample (recycleSamples), emptied: no allocation once warm.
    out.manifolds = std::move(ps.spare_manifolds);
    out.manifold_part = std::move(ps.spare_manifold_part);
    out.parts = std::move(ps.spare_parts);
    out.manifolds.clear();
    out.manifold_part.clear();
    out.parts.clear();
    thread_local ContactPatch patch;  // per worker; refilled for every manifold
    // Speculative regime: two held bodies (or one and the ground) within reach of each other are in
    // their islands' solve with speculative points: no event is scheduled for them; a pair with a
    // body in flight keeps the exact schedule (the queue) and becomes a manifold at touching.
    const double t = valid_at_[static_cast<std::size_t>(ps.a)];
    // Fixed ticks: every pair within reach is in its island's solve (nothing else would meet it).
    const double window =
        reach > cd && (fixedTicks(settings_.touching) || (heldAt(ps.a, t) && heldAt(ps.b, t))) ? reach : cd;
    // A compound pair skips part pairs whose balls are farther apart than the pair can close within
    // a frame (a box in a drum of 30 slabs queries the two or three near it); their gap is a lower
    // bound (the balls' gap, or a ball against the other part's box).
    const bool compound = sa.parts.size() * sb.parts.size() > 1;
    const double far_gap = compound ? window + closingSpeed(ps, frame_dt_) * frame_dt_ : kNever;
    auto addGap = [&out](const PartGap& g) {
        out.parts.push_back(g);
        if (g.distance < out.distance) {
            out.distance = g.distance;
            out.normal = g.normal;
        }
    };
    auto addManifold = [&](ContactManifold& m, std::size_t part_pair) {
        m.body_a = ps.a;
        m.body_b = ps.b;
        m.pair = pair_index;
        m.restitution = mat.restitution;
        m.friction = mat.friction;
        out.manifolds.push_back(std::move(m));
        out.manifold_part.push_back(static_cast<int>(part_pair));
    };
    for (std::size_t i = 0; i < sa.parts.size(); ++i) {
        const Pose pa = fa * sa.parts[i].local;
        const Vec3 ca = compound ? fa.apply(sa.parts[i].bound_center) : Vec3::Zero();
        for (std::size_t j = 0; j < sb.parts.size(); ++j) {
            const std::size_t part_pair = i * sb.parts.size() + j;
            if (compound) {
                // Most part pairs of a compound are far apart (a box in a drum of 30 slabs): their
                // test composes no part pose, and writes the anchor only if it was valid.
                const Vec3 cb = fb.apply(sb.parts[j].bound_center);
                const double apart = (cb - ca).norm();
                // The balls' gap, and each ball against the other part's own box (a box by a long slab).
                double gap = apart - sa.parts[i].bound_radius - sb.parts[j].bound_radius;
                if (!(gap > far_gap))
                    gap = std::max({gap, sb.parts[j].gapToBall(fb * sb.parts[j].local, ca, sa.parts[i].bound_radius),
                                    sa.parts[i].gapToBall(pa, cb, sb.parts[j].bound_radius)});
                if (gap > far_gap) {
                    addGap({gap, Vec3((cb - ca) / apart), true});
                    ManifoldAnchor& anchor = ps.anchors[part_pair];
                    if (anchor.valid) anchor.valid = false;
                    continue;
                }
            }
            const Pose pb = fb * sb.parts[j].local;
            ManifoldAnchor& anchor = ps.anchors[part_pair];
            // A touching part pair whose bodies barely moved relative to each other since its last
            // query keeps that manifold, carried along by the motion (manifold_anchor.h): a resting
            // pile's pairs are not walked and clipped again at every solve.
            if (anchor.valid && anchor.window >= window && settings_.manifold_reuse > 0.0) {
                ContactManifold m;
                if (anchoredMotion(anchor, fa, fb, sa.parts[i].frame_radius, sb.parts[j].frame_radius) <=
                        settings_.manifold_reuse * cd &&
                    carryManifold(anchor, fa, fb, m)) {
                    addGap({m.distance, m.normal});
                    addManifold(m, part_pair);
                    ++out.carried;
                    continue;
                }
            }
            FeatureCache& cache = ps.caches[part_pair];
            const ProximityResult r = queryParts(sa.parts[i], pa, sb.parts[j], pb, cache);
            ++out.queries;
            out.walk_steps += r.walk_steps;
            out.max_walk = std::max(out.max_walk, r.walk_steps);
            if (!r.converged) ++out.not_converged;
            addGap({r.distance, r.normal});
            anchor.valid = false;
            if (!(r.distance < window)) continue;
            ContactManifold m;
            m.normal = r.normal;
            m.distance = r.distance;
            partPatch(sa.parts[i], pa, sb.parts[j], pb, cache, r, cd, reach, patch);
            setManifoldPoints(patch, r, cd, reach > cd, m);
            anchorManifold(m, fa, fb, window, anchor);
            addManifold(m, part_pair);
        }
    }
    return out;
}

double NativeBackend::closingSpeed(const PairState& ps, double tick) const {
    const RigidBody& a = bodies_[static_cast<std::size_t>(ps.a)];
    const RigidBody& b = bodies_[static_cast<std::size_t>(ps.b)];
    const bool one_ground = infinite_mass_[static_cast<std::size_t>(ps.a)] != infinite_mass_[static_cast<std::size_t>(ps.b)];
    return (b.velocity - a.velocity).norm() +
           a.maxAngularSpeed() * shapes_[static_cast<std::size_t>(ps.a)].outer_radius +
           b.maxAngularSpeed() * shapes_[static_cast<std::size_t>(ps.b)].outer_radius +
           (one_ground ? scene_.gravity.norm() * tick : 0.0);
}

double NativeBackend::smallerInnerRadius(const PairState& ps, bool awake_only) const {
    double size = kNever;
    for (int body : {ps.a, ps.b}) {
        const auto b = static_cast<std::size_t>(body);
        if (!infinite_mass_[b] && !(awake_only && asleep_[b] != 0)) size = std::min(size, shapes_[b].reach_radius);
    }
    return size;
}

double NativeBackend::patchReach(const PairState& ps) const {
    const double cd = scene_.collision_distance;
    if (!onGrid(settings_.touching)) return cd;
    // What the pair can close over the longest tick (1.5 sub-steps, after an off-grid solve).
    // Capped at a quarter of the smaller body's inner radius: a feature farther than that is not
    // part of this contact, a wide tolerance would let in faces of a rounded hull, and the patch
    // (the reference and incident faces, contact_patch.h) holds only the features of one face: a
    // body turning farther brings down corners of another.
    // Fixed ticks: the tick itself (frame_dt_ is the tick being stepped).
    const double tick = fixedTicks(settings_.touching)
                            ? frame_dt_
                            : kLongestTick * frame_dt_ / static_cast<double>(settings_.contact_substeps);
    const double reach = std::min(closingSpeed(ps, tick) * tick, settings_.speculativeReach() * smallerInnerRadius(ps));
    return cd + (std::isfinite(reach) && reach > 0.0 ? reach : 0.0);
}

void NativeBackend::setManifoldPoints(const ContactPatch& patch, const ProximityResult& r, double cd, bool speculative,
                                      ContactManifold& m) {
    // Without speculative contact every point of the patch counts as touching, as in issue 9: the
    // polygon's four extremes, no gaps (every point at the closest distance), the area centroid.
    if (!speculative) {
        const auto keep = reduceContactPointIndices(patch.points, r.normal);
        for (std::size_t k : keep) m.points.push_back(patch.points[k]);
        if (m.points.empty()) m.points.push_back(patch.centroid);
        m.centroid = patch.centroid;
        return;
    }
    // What touches keeps the polygon's extremes (at most four: the block solve's symmetric split);
    // the speculative points keep their own four, the deepest first (Bullet's and Box2D's rule), so
    // a tipping body's far vertices are never traded for one more point of the face it rests on.
    InlineVector<std::size_t, kMaxManifoldSlots> keep;
    // The front: what touches, or (nothing touching yet) the points within the collision distance of
    // the closest, which meet first (a box landing on an edge: both ends of the edge, not one end
    // and a vertex of the face above it).
    double closest = kNever;
    for (std::size_t k = 0; k < patch.points.size(); ++k)
        closest = std::min(closest, k < patch.gaps.size() ? patch.gaps[k] : r.distance);
    const double front = std::max(cd, closest + cd);
    // Per-thread scratch (the narrow phase runs on several workers): no allocation once warm.
    thread_local std::vector<Vec3> pts;
    thread_local std::vector<double> gaps;
    thread_local std::vector<std::size_t> index;
    for (int side = 0; side < 2; ++side) {
        pts.clear();
        gaps.clear();
        index.clear();
        for (std::size_t k = 0; k < patch.points.size(); ++k) {
            const double gap = k < patch.gaps.size() ? patch.gaps[k] : r.distance;
            if ((gap < front) != (side == 0)) continue;
            pts.push_back(patch.points[k]);
            gaps.push_back(gap);
            index.push_back(k);
        }
        for (std::size_t k : reduceContactPointIndices(
                 pts, r.normal, side == 0 ? std::span<const double>{} : std::span<const double>(gaps)))
            keep.push_back(index[k]);
    }
    bool beyond = false;   // some point is beyond the collision distance
    for (std::size_t k : keep) {
        m.points.push_back(patch.points[k]);
        const double gap = k < patch.gaps.size() ? patch.gaps[k] : r.distance;
        m.point_gap.push_back(gap);
        beyond = beyond || !(gap < cd);
    }
    m.centroid = patch.centroid;
    if (m.points.empty()) {
        m.points.push_back(patch.centroid);
        m.point_gap.push_back(r.distance);
        return;
    }
    // The collision phase acts at the centroid of what touches now, never at a speculative point.
    if (beyond) {
        Vec3 sum = Vec3::Zero();
        int touching = 0;
        for (std::size_t k = 0; k < m.points.size(); ++k)
            if (m.point_gap[k] < cd) {
                sum += m.points[k];
                ++touching;
            }
        m.centroid = touching > 0 ? Vec3(sum / touching) : Vec3(0.5 * (r.point_a + r.point_b));
    }
}

void NativeBackend::samplePairs(const std::vector<int>& pairs, double t, std::vector<PairSample>& samples) {
    // Bodies are brought to t serially (the result is thread-count free); a pair's sample is then a
    // pure function of that pair, so any worker count gives the same bits.
    for (int idx : pairs) {
        const PairState& ps = pairs_[static_cast<std::size_t>(idx)];
        syncBody(ps.a, t);
        syncBody(ps.b, t);
    }
    // `samples` keeps its storage from step to step (its elements' vectors went back to their
    // pairs in recycleSamples); each slot is overwritten by its pair's sample.
    samples.resize(pairs.size());
    if (pairs.size() < kMinParallelPairs) {
        for (std::size_t k = 0; k < pairs.size(); ++k) samples[k] = samplePair(pairs[k]);
    } else {
        // One reference captured: std::function stores it in place (no allocation per call).
        auto sampleOne = [this, &pairs, &samples](std::size_t k) { samples[k] = samplePair(pairs[k]); };
        partition_->run(pairs.size(), [&sampleOne](std::size_t k, int) { sampleOne(k); });
    }
    for (const PairSample& s : samples) pairs_[static_cast<std::size_t>(s.pair)].sampled_step = step_index_;
}

void NativeBackend::recycleSamples(std::vector<PairSample>& samples) {
    for (PairSample& s : samples) {
        PairState& ps = pairs_[static_cast<std::size_t>(s.pair)];
        ps.spare_manifolds = std::move(s.manifolds);
        ps.spare_manifold_part = std::move(s.manifold_part);
        ps.spare_parts = std::move(s.parts);
    }
}

void NativeBackend::recordSamples(const std::vector<PairSample>& samples) {
    for (const PairSample& s : samples) {
        stats_.narrow_queries += s.queries;
        stats_.carried_manifolds += s.carried;
        stats_.walk_steps += s.walk_steps;
        stats_.max_walk_steps = std::max<std::int64_t>(stats_.max_walk_steps, s.max_walk);
        if (s.not_converged > 0) warn("walk_not_converged", static_cast<std::uint64_t>(s.not_converged));
        if (!std::isfinite(s.distance)) warn("nonfinite_distance");
        // The solver's position pass repairs penetration shallower than the collision distance;
        // deeper is an emergency (counted), repaired by moving the bodies.
        // Fixed ticks let a feature no patch held (a corner of another face turned down within the
        // tick) sink deeper; the contact phase pushes it out, as Bullet's and Box2D's do, up to half
        // the smaller body's inner radius (a quarter of its thickness).
        const double repair_below =
            fixedTicks(settings_.touching)
                ? -std::max(scene_.collision_distance,
                            kFixedRepairDepth * smallerInnerRadius(pairs_[static_cast<std::size_t>(s.pair)]))
                : -scene_.collision_distance;
        if (s.distance < 0.0) stats_.deepest_penetration = std::max(stats_.deepest_penetration, -s.distance);
        if (s.distance < repair_below) separatePenetrating(s);
    }
}

double NativeBackend::bouncingSphereRecheck(const PairSample& s, double t) const {
    const PairState& ps = pairs_[static_cast<std::size_t>(s.pair)];
    // (a truly static partner: a tracked one moves, and its pairs are not refined here)
    const bool a_static = bodies_[static_cast<std::size_t>(ps.a)].is_static, b_static = bodies_[static_cast<std::size_t>(ps.b)].is_static;
    if (a_static == b_static || ps.placed_in_window) return -1.0;   // placed resting: no refinement
    const int sphere = a_static ? ps.b : ps.a;
    const BodyShape& sh = shapes_[static_cast<std::size_t>(sphere)];
    if (sh.parts.size() != 1 || !sh.parts[0].is_sphere) return -1.0;
    if (drift_until_[static_cast<std::size_t>(sphere)] > t) return -1.0;   // held by the contact phase
    // Normal speed away from the static body (a sphere's spin adds nothing along the normal).
    const double away = (a_static ? 1.0 : -1.0) * bodies_[static_cast<std::size_t>(sphere)].velocity.dot(s.normal);
    if (!(away > 0.0)) return -1.0;
    const double clear = kRecheckGapPerSize * (sh.outer_radius + shapes_[static_cast<std::size_t>(a_static ? ps.a : ps.b)].outer_radius);
    if (!(s.distance < clear)) return -1.0;
    return (clear - s.distance) / away;
}

double NativeBackend::closeTime(const PairState& ps, std::size_t part_pair, const PartGap& g, double allowed,
                                double floor, const MotionBound& ma, const MotionBound& mb, double t,
                                double horizon) const {
    // Two far part balls: no separating direction is known, so the direction-free bound.
    if (g.bounded) return earliestCollisionTime(allowed, ma, mb, horizon);
    const double pair_time = earliestCollisionTime(allowed, g.normal, ma, mb, horizon);
    if (!(pair_time < horizon)) return pair_time;
    // A rotating body's far vertices start from their own gaps, and its held contact points approach
    // at their solved speed: the per-point bound is much longer for a tumbling box. Both are safe,
    // so the longer one is.
    return std::max(pair_time, supportPointTime(ps, part_pair, g.normal, floor, t, horizon));
}

double NativeBackend::supportPointTime(const PairState& ps, std::size_t part_pair, const Vec3& normal, double floor,
                                       double t, double horizon) const {
    const std::optional<RigidMotion> ma = rigidMotion(ps.a, t, horizon);
    const std::optional<RigidMotion> mb = rigidMotion(ps.b, t, horizon);
    if (!ma || !mb) return 0.0;
    const BodyShape& sa = shapes_[static_cast<std::size_t>(ps.a)];
    const BodyShape& sb = shapes_[static_cast<std::size_t>(ps.b)];
    const ConvexPart& pa = sa.parts[part_pair / sb.parts.size()];
    const ConvexPart& pb = sb.parts[part_pair % sb.parts.size()];
    const SupportPoints a = pa.supportPoints(bodies_[static_cast<std::size_t>(ps.a)].framePose() * pa.local);
    const SupportPoints b = pb.supportPoints(bodies_[static_cast<std::size_t>(ps.b)].framePose() * pb.local);
    return vertexApproachTime(a, *ma, b, *mb, normal, floor, horizon);
}

void NativeBackend::scheduleSampled(const PairSample& s, double t, bool solved) {
    PairState& ps = pairs_[static_cast<std::size_t>(s.pair)];
    const double cd = scene_.collision_distance;
    const bool touching = !s.manifolds.empty();
    ps.touching = touching;
    ps.in_contact = touching && s.distance < cd;
    ps.sampled_once = true;
    double until_a = kNever, until_b = kNever;
    const MotionBound ma = motionBound(ps.a, until_a);
    const MotionBound mb = motionBound(ps.b, until_b);
    const double horizon = std::min(kQueueHorizon, std::min(until_a, until_b) - t);
    if (!touching) {
        if (touching_.erase(s.pair) > 0) ticks_dirty_ = true;
        double key = t + std::max(0.0, horizon);
        if (s.deferred) {
            key = s.contact_time;   // certified by the contact time refinement
        } else {
            const double window = std::max(0.0, horizon);
            for (std::size_t k = 0; k < s.parts.size(); ++k)
                key = std::min(key, t + closeTime(ps, k, s.parts[k], s.parts[k].distance - kApproachTarget * cd,
                                                  kApproachTarget * cd, ma, mb, t, window));
        }
        queue_.push(s.pair, ps.a, ps.b, key);
        return;
    }
    if (touching_.insert(s.pair).second) ticks_dirty_ = true;
    queue_.removePair(s.pair);
    // A touching pair is held by its island's contact phase at its contact points to first order;
    // rotation can bring other features down, a free body can fall back, a new contact has had no
    // solve yet. So the island is solved again before the pair can close too far (motion bounds; a
    // resting pile's bounds are long, a tumbling body's short). A pair solved with both bodies
    // drifting may close to kSolvedFloor (the next solve's position pass repairs that); any other
    // touching pair only to the floor of the window.
    auto drifting = [&](int body) {
        return infinite_mass_[static_cast<std::size_t>(body)] || drift_until_[static_cast<std::size_t>(body)] > t;
    };
    const bool held = solved && drifting(ps.a) && drifting(ps.b);
    double bound = std::max(0.0, horizon);
    // Speculative regime: a part pair the solve held (both bodies drifting) waits for its island's
    // grid tick; what may close within the tick was in the solve as speculative points.
    // Soft regime: every part pair the solve held within the pair's reach waits for the grid (it
    // was in the solve as speculative points, and the sub-steps followed the bodies' turning); a
    // part pair beyond the reach keeps a bound, and so does every part pair of a pair that may
    // close farther than the capped reach within a tick (a fast body: the speculative points cannot
    // stand for all it may meet). A pair that only now touches (not solved) was in no solve: it
    // keeps its bounds, so its island is solved before it closes.
    const bool soft = held && settings_.touching == TouchingRegime::Soft;
    const bool speculative = held && settings_.touching == TouchingRegime::Speculative;
    bool covers_tick = false;
    if (soft) {
        // What the pair may close before its island's next tick, at its speeds after the solve,
        // against what the manifolds reached when they were built.
        double tick_end = kNever;
        for (int body : {ps.a, ps.b})
            if (!infinite_mass_[static_cast<std::size_t>(body)])
                tick_end = std::min(tick_end, tick_end_[static_cast<std::size_t>(body)]);
        const double tick = tick_end - t;
        covers_tick = tick < kNever && closingSpeed(ps, tick) * tick <= s.reach - cd;
    }
    for (std::size_t k = 0; k < s.parts.size(); ++k) {
        const PartGap& g = s.parts[k];
        if (speculative && g.distance < cd) continue;
        if (covers_tick && g.distance < s.reach) continue;
        const double allowed =
            held ? g.distance - kSolvedFloor * cd
                 : (g.distance < cd ? std::max(g.distance - kTouchingFloor * cd, kTouchingMinAllowance * cd)
                                    : g.distance - kApproachTarget * cd);
        bound = std::min(bound, closeTime(ps, k, g, allowed, g.distance - allowed, ma, mb, t, bound));
    }
    // A sphere that just bounced off a static body flies freely inside the window: it is looked at
    // again as soon as it is clear of touching, so that the contact time refinement (deferImpacts)
    // takes it from there and meets its next impact at touching, exactly (issue 4's bounce apexes
    // and rest time), instead of a protection bound letting it sink into the floor.
    if (const double rise = bouncingSphereRecheck(s, t); rise >= 0.0) bound = std::min(bound, rise);
    // A held pair already at its floor does not call for another solve at once (the one that just
    // ran is repairing it): the next comes after a fraction of the tick at the earliest. This
    // keeps a squeezed body from freezing time in zero-length steps.
    if (held) bound = std::max(bound, kHeldMinTick * frame_dt_ / static_cast<double>(settings_.contact_substeps));
    for (int body : {ps.a, ps.b})
        if (!infinite_mass_[static_cast<std::size_t>(body)])
            setTick(body, std::min(tick_end_[static_cast<std::size_t>(body)], t + bound));
}

}  // namespace vroc::native
