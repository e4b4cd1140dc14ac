// SPDX-License-Identifier: MIT
#include "backend/native_backend.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "backend/part_query.h"
#include "dynamics/free_flight.h"
#include "dynamics/newton_coulomb.h"
#include "dynamics/vroc1995_impulse.h"
#include "scheduling/collision_time_bound.h"
#include "vroc/core/errors.h"

namespace vroc::native {
namespace {

// Separation targets as fractions of the collision distance (docs/native-dynamics.md):
// free pairs advance to >= 3/4 of it; touching pairs may close to 1/4 (never to 0).
constexpr double kApproachTarget = 0.75;
constexpr double kTouchingFloor = 0.25;
constexpr double kTouchingMinAllowance = 0.125;
// How far ahead [s] a pair's earliest collision time is computed for the queue.
constexpr double kQueueHorizon = 1.0;
// Due pairs below this count are sampled on the calling thread (see internalStep).
constexpr std::size_t kMinParallelPairs = 8;

}  // namespace

NativeBackend::NativeBackend(const Scene& scene, const NativeSettings& settings)
    : scene_(scene), settings_(settings) {
    if (!(scene.collision_distance > 0.0))
        throw InputError("scene '" + scene.name + "': collision_distance must be > 0 for the native backend");
    for (const Body& body : scene.bodies) {
        bodies_.push_back(RigidBody::fromScene(body));
        try {
            shapes_.push_back(BodyShape::fromScene(body.shape, bodies_.back().com_offset));
        } catch (const GeometryError& e) {
            throw InputError("scene '" + scene.name + "', body '" + body.name + "': " + e.what());
        }
        versions_.push_back(0);
        valid_at_.push_back(0.0);
        box_dirty_.push_back(1);
    }
    imp_.assign(bodies_.size(), BodyImpulse{});
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        const RigidBody& rb = bodies_[i];
        broad_phase_.addBody(shapes_[i].worldAabb(rb.framePose()).inflated(scene.collision_distance),
                             rb.is_static);
    }
    partition_ = std::make_unique<PairPartition>(settings_.threads);
}

BodyState NativeBackend::bodyState(int body) const {
    const RigidBody& rb = bodies_.at(static_cast<std::size_t>(body));
    BodyState s;
    s.pose = rb.framePose();
    s.linear_velocity = rb.velocity;
    s.angular_velocity = rb.angularVelocity();
    return s;
}

void NativeBackend::setBodyState(int body, const BodyState& state) {
    RigidBody& rb = bodies_.at(static_cast<std::size_t>(body));
    if (rb.is_static) return;
    if (!state.pose.position.allFinite() || !state.pose.orientation.coeffs().allFinite() ||
        !state.linear_velocity.allFinite() || !state.angular_velocity.allFinite()) {
        warn("nonfinite_state");
        return;
    }
    rb.setFromState(state.pose, state.linear_velocity, state.angular_velocity);
    bumpVersion(body);
}

void NativeBackend::applyImpulse(int body, const Vec3& impulse, const Vec3& world_point) {
    RigidBody& rb = bodies_.at(static_cast<std::size_t>(body));
    if (rb.is_static) return;
    if (!impulse.allFinite() || !world_point.allFinite()) {
        warn("nonfinite_state");
        return;
    }
    rb.applyImpulse(impulse, world_point);
    bumpVersion(body);
}

std::vector<CollisionEvent> NativeBackend::takeEvents() {
    std::vector<CollisionEvent> out;
    out.swap(events_);
    return out;
}

void NativeBackend::stepFrame(double dt) {
    if (!(dt > 0.0) || !std::isfinite(dt)) {
        warn("invalid_frame_dt");
        return;
    }
    const double frame_start = time_;
    frame_end_ = frame_start + dt;
    // Every body is valid at the frame start here; its box is swept over the whole frame.
    updateBroadPhase(true);
    double elapsed = 0.0;
    std::int64_t steps = 0;
    while (elapsed < dt) {
        const bool unbounded = steps >= settings_.max_internal_steps;
        if (unbounded) warn("internal_step_cap");
        const double h = internalStep(frame_start, elapsed, dt - elapsed, unbounded);
        ++steps;
        elapsed = (h >= dt - elapsed) ? dt : elapsed + h;
    }
    time_ = frame_end_;
    for (std::size_t i = 0; i < bodies_.size(); ++i) syncBody(static_cast<int>(i), time_);
    ++stats_.frames;
    stats_.internal_steps += steps;
    stats_.max_internal_steps_per_frame = std::max(stats_.max_internal_steps_per_frame, steps);
}

NativeBackend::PairState& NativeBackend::pairState(int a, int b) {
    const std::uint64_t key = (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
                              static_cast<std::uint32_t>(b);
    auto [it, inserted] = pair_index_.try_emplace(key, static_cast<int>(pairs_.size()));
    if (inserted) {
        PairState ps;
        ps.a = a;
        ps.b = b;
        ps.caches.resize(shapes_[a].parts.size() * shapes_[b].parts.size());
        pairs_.push_back(std::move(ps));
    }
    return pairs_[static_cast<std::size_t>(it->second)];
}

MotionBound NativeBackend::ballisticBound(int body) const {
    const RigidBody& rb = bodies_[static_cast<std::size_t>(body)];
    if (rb.is_static) return MotionBound::stationary();
    MotionBound m;
    m.velocity = rb.velocity;
    m.acceleration = scene_.gravity;
    m.angular_speed = rb.maxAngularSpeed();
    m.outer_radius = shapes_[body].outer_radius;
    m.inner_radius = shapes_[body].inner_radius;
    return m;
}

void NativeBackend::updateBroadPhase(bool all) {
    // A box swept from the body's valid time to the frame end stays valid while the body flies
    // ballistically, so only bodies whose velocity or position was changed need a new one.
    bool changed = false;
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        if (!all && box_dirty_[i] == 0) continue;
        box_dirty_[i] = 0;
        const RigidBody& rb = bodies_[i];
        if (rb.is_static) continue;
        const double r = shapes_[i].outer_radius;
        const Aabb now{rb.com - Vec3::Constant(r), rb.com + Vec3::Constant(r)};
        const double span = std::max(0.0, frame_end_ - valid_at_[i]);
        broad_phase_.setAabb(static_cast<int>(i),
                             ballisticBound(static_cast<int>(i)).sweptAabb(now, span)
                                 .inflated(scene_.collision_distance));
        changed = true;
    }
    if (!changed && !all) return;
    broad_phase_.update();
    candidates_.clear();
    candidates_.reserve(broad_phase_.pairs().size());
    for (const BodyPair& bp : broad_phase_.pairs()) {
        const PairState& ps = pairState(bp.a, bp.b);
        candidates_.push_back(static_cast<int>(&ps - pairs_.data()));
    }
}

void NativeBackend::syncBody(int body, double t) {
    const std::size_t i = static_cast<std::size_t>(body);
    if (!(valid_at_[i] < t)) return;
    const double h = t - valid_at_[i];
    valid_at_[i] = t;
    RigidBody& rb = bodies_[i];
    if (rb.is_static) return;
    const RigidBody saved = rb;
    advanceBallistic(rb, h, scene_.gravity);
    advanceTorqueFree(rb, h);
    recoverIfNonFinite(body, saved);
}

NativeBackend::PairSample NativeBackend::samplePair(int pair_index) {
    PairState& ps = pairs_[static_cast<std::size_t>(pair_index)];
    PairSample out;
    out.pair = pair_index;
    out.distance = std::numeric_limits<double>::infinity();
    const BodyShape& sa = shapes_[ps.a];
    const BodyShape& sb = shapes_[ps.b];
    const Pose fa = bodies_[ps.a].framePose();
    const Pose fb = bodies_[ps.b].framePose();
    const ContactMaterial mat = combineMaterials(scene_.materials[scene_.bodies[ps.a].material],
                                                 scene_.materials[scene_.bodies[ps.b].material]);
    const double cd = scene_.collision_distance;
    for (std::size_t i = 0; i < sa.parts.size(); ++i) {
        const Pose pa = fa * sa.parts[i].local;
        for (std::size_t j = 0; j < sb.parts.size(); ++j) {
            const Pose pb = fb * sb.parts[j].local;
            FeatureCache& cache = ps.caches[i * sb.parts.size() + j];
            const ProximityResult r = queryParts(sa.parts[i], pa, sb.parts[j], pb, cache);
            ++out.queries;
            out.walk_steps += r.walk_steps;
            out.max_walk = std::max(out.max_walk, r.walk_steps);
            if (!r.converged) ++out.not_converged;
            out.parts.push_back({r.distance, r.normal});
            if (r.distance < out.distance) {
                out.distance = r.distance;
                out.normal = r.normal;
            }
            if (!(r.distance < cd)) continue;
            ContactManifold m;
            m.body_a = ps.a;
            m.body_b = ps.b;
            m.pair = pair_index;
            m.normal = r.normal;
            m.distance = r.distance;
            const ContactPatch patch = partPatch(sa.parts[i], pa, sb.parts[j], pb, cache, r, cd);
            m.centroid = patch.centroid;
            m.points = patch.points;
            if (m.points.empty()) m.points.push_back(patch.centroid);
            m.restitution = mat.restitution;
            m.friction = mat.friction;
            out.manifolds.push_back(std::move(m));
        }
    }
    return out;
}

void NativeBackend::collisionPhase(std::vector<ContactManifold>& manifolds) {
    for (int sweep = 0; sweep < settings_.collision_iterations; ++sweep) {
        bool any = false;
        for (ContactManifold& m : manifolds) {
            RigidBody& a = bodies_[m.body_a];
            RigidBody& b = bodies_[m.body_b];
            const Vec3 u = b.pointVelocity(m.centroid) - a.pointVelocity(m.centroid);
            const double un = u.dot(m.normal);
            if (!(un < 0.0)) continue;
            const double e = -un < settings_.restitution_threshold ? 0.0 : m.restitution;
            const ImpulseResult r =
                settings_.response == ResponseModel::Vroc1995
                    ? vroc1995Impulse(a, b, m.centroid, m.normal, e)
                    : newtonCoulombImpulse(a, b, m.centroid, m.normal, e, m.friction);
            if (r.trouble == ImpulseTrouble::IllConditioned) warn("ill_conditioned_solve");
            if (r.trouble == ImpulseTrouble::Degenerate) warn("degenerate_contact");
            if (!r.impulse.allFinite()) {
                warn("nonfinite_state");
                continue;
            }
            if (r.impulse.isZero(0.0)) continue;
            a.applyImpulse(-r.impulse, m.centroid);
            b.applyImpulse(r.impulse, m.centroid);
            bumpVersion(m.body_a);
            bumpVersion(m.body_b);
            m.collision_impulse += std::max(0.0, r.impulse.dot(m.normal));
            any = true;
        }
        if (!any) break;
    }
}

MotionBound NativeBackend::stepBound(int body, const BodyImpulse& imp, double h) const {
    if (!imp.supported) return ballisticBound(body);
    const RigidBody& rb = bodies_[static_cast<std::size_t>(body)];
    MotionBound m = ballisticBound(body);
    const Vec3 v_end = rb.velocity + scene_.gravity * h + rb.inv_mass * imp.linear;
    m.velocity = 0.5 * (rb.velocity + v_end);   // supported bodies move with the mean velocity
    m.acceleration = Vec3::Zero();
    if (rb.smallest_moment > 0.0)
        m.angular_speed = std::max(rb.angular_momentum.norm(), (rb.angular_momentum + imp.angular).norm()) /
                          rb.smallest_moment;
    return m;
}

double NativeBackend::contactBoundedStep(const std::vector<PairSample>& samples,
                                         const std::vector<BodyImpulse>& imp, double h) const {
    const double cd = scene_.collision_distance;
    double best = h;
    for (const PairSample& s : samples) {
        if (s.deferred) continue;   // its flight to the contact time is certified by deferImpacts
        const PairState& ps = pairs_[static_cast<std::size_t>(s.pair)];
        const MotionBound ma = stepBound(ps.a, imp[ps.a], h);
        const MotionBound mb = stepBound(ps.b, imp[ps.b], h);
        for (const PairSample::PartGap& g : s.parts) {
            const bool touching = g.distance < cd;
            const double allowed = touching ? std::max(g.distance - kTouchingFloor * cd, kTouchingMinAllowance * cd)
                                            : g.distance - kApproachTarget * cd;
            const double t = earliestCollisionTime(allowed, g.normal, ma, mb, best);
            if (t < best) best = t;
        }
    }
    return best;
}

double NativeBackend::internalStep(double frame_start, double elapsed, double remaining, bool unbounded) {
    const double t = frame_start + elapsed;
    const double cd = scene_.collision_distance;
    ++step_index_;
    updateBroadPhase(false);

    // The queue: a pair is queried only when its earliest possible collision time has come or a
    // body's velocity changed since its key was computed; the others only bound the step.
    stats_.broad_phase_pairs += static_cast<std::int64_t>(candidates_.size());
    std::vector<int> due;
    double h = remaining;
    for (int idx : candidates_) {
        const PairState& ps = pairs_[static_cast<std::size_t>(idx)];
        const bool stale = ps.version_a != versions_[ps.a] || ps.version_b != versions_[ps.b];
        if (stale || !(ps.safe_until > t)) {
            due.push_back(idx);
        } else {
            ++stats_.queue_skips;
            if (!unbounded) h = std::min(h, ps.safe_until - t);
        }
    }
    stats_.queue_pops += static_cast<std::int64_t>(due.size());
    // Only the bodies of due pairs are brought to t (serially: the result is thread-count free).
    for (int idx : due) {
        const PairState& ps = pairs_[static_cast<std::size_t>(idx)];
        syncBody(ps.a, t);
        syncBody(ps.b, t);
    }

    // A pair's sample is a pure function of that pair, so running a short list on the calling
    // thread (waking the pool costs more than a few queries) gives the same bits.
    std::vector<PairSample> samples;
    if (due.size() < kMinParallelPairs) {
        samples.reserve(due.size());
        for (int idx : due) samples.push_back(samplePair(idx));
    } else {
        samples = partition_->map<PairSample>(due.size(), [&](std::size_t k) { return samplePair(due[k]); });
    }
    if (!unbounded) h = deferImpacts(samples, t, h);
    std::vector<ContactManifold> manifolds;
    for (const PairSample& s : samples) {
        stats_.narrow_queries += s.queries;
        stats_.walk_steps += s.walk_steps;
        stats_.max_walk_steps = std::max<std::int64_t>(stats_.max_walk_steps, s.max_walk);
        if (s.not_converged > 0) warn("walk_not_converged", static_cast<std::uint64_t>(s.not_converged));
        if (!std::isfinite(s.distance)) warn("nonfinite_distance");
        if (s.distance < 0.0) separatePenetrating(s);
        manifolds.insert(manifolds.end(), s.manifolds.begin(), s.manifolds.end());
    }
    stats_.contacts += static_cast<std::int64_t>(manifolds.size());

    collisionPhase(manifolds);

    // Contact phase for the tentative step, shortened until no pair can close below its target.
    ContactSolverSettings solver;
    solver.model = settings_.response;
    solver.iterations = settings_.contact_iterations;
    solver.shock_iterations = settings_.shock_iterations;
    for (int id : imp_ids_) imp_[static_cast<std::size_t>(id)] = BodyImpulse{};
    imp_ids_.clear();
    const std::vector<BodyImpulse>& imp = imp_;
    const double h_min = std::min(remaining, 1e-9);
    bool limited = false;
    for (int round = 0;; ++round) {
        if (!manifolds.empty()) {
            solveContacts(manifolds, h, solver);
        }
        if (unbounded || round == 4) break;
        const double hb = contactBoundedStep(samples, imp, h);
        if (!(hb < h)) break;
        limited = true;
        if (hb < h_min) warn("zeno_contact");
        h = std::max(hb, h_min);
    }
    if (limited) ++stats_.toi_limited_steps;

    emitEvents(samples, manifolds, t);
    for (const PairSample& s : samples) {
        PairState& ps = pairs_[static_cast<std::size_t>(s.pair)];
        ps.touching = !s.manifolds.empty();
        ps.touching_step = step_index_;
        ps.version_a = versions_[ps.a];
        ps.version_b = versions_[ps.b];
        if (ps.touching) {
            ps.safe_until = t;
            continue;
        }
        double tc = kQueueHorizon;
        for (const PairSample::PartGap& g : s.parts) {
            tc = std::min(tc, earliestCollisionTime(g.distance - cd, g.normal, ballisticBound(ps.a),
                                                    ballisticBound(ps.b), kQueueHorizon));
        }
        ps.safe_until = t + tc;
    }
    const double t_next = (h >= remaining) ? frame_end_ : frame_start + (elapsed + h);
    advanceBodies(imp, h, t_next);
    return h;
}

void NativeBackend::separatePenetrating(const PairSample& s) {
    // Recovery only: steps are bounded so pairs stop at a positive separation. Move the bodies
    // apart along the normal (by inverse mass) to half the collision distance.
    const PairState& ps = pairs_[static_cast<std::size_t>(s.pair)];
    RigidBody& a = bodies_[ps.a];
    RigidBody& b = bodies_[ps.b];
    const double w = a.inv_mass + b.inv_mass;
    if (!(w > 0.0) || !s.normal.allFinite()) return;
    warn("penetration_recovered");
    const double push = 0.5 * scene_.collision_distance - s.distance;
    a.com -= (a.inv_mass / w) * push * s.normal;
    b.com += (b.inv_mass / w) * push * s.normal;
    box_dirty_[static_cast<std::size_t>(ps.a)] = 1;
    box_dirty_[static_cast<std::size_t>(ps.b)] = 1;
}

void NativeBackend::solveContacts(std::vector<ContactManifold>& manifolds, double h,
                                  const ContactSolverSettings& solver) {
    // Compact to the touched bodies, ascending index (same order as the full list, so the
    // solver's sweeps and levels are unchanged), solve, and scatter the impulses back.
    std::vector<int> ids;
    for (const ContactManifold& m : manifolds) {
        ids.push_back(m.body_a);
        ids.push_back(m.body_b);
    }
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    std::vector<RigidBody> local;
    local.reserve(ids.size());
    for (int id : ids) local.push_back(bodies_[static_cast<std::size_t>(id)]);
    auto localOf = [&](int id) {
        return static_cast<int>(std::lower_bound(ids.begin(), ids.end(), id) - ids.begin());
    };
    std::vector<ContactManifold> lm = manifolds;
    for (ContactManifold& m : lm) {
        m.body_a = localOf(m.body_a);
        m.body_b = localOf(m.body_b);
    }
    std::vector<BodyImpulse> li;
    const ContactSolverReport rep = solveContactPhase(local, lm, h, scene_.gravity, solver, li);
    for (std::size_t m = 0; m < manifolds.size(); ++m) manifolds[m].contact_impulse = lm[m].contact_impulse;
    for (int id : imp_ids_) imp_[static_cast<std::size_t>(id)] = BodyImpulse{};
    for (std::size_t k = 0; k < ids.size(); ++k) imp_[static_cast<std::size_t>(ids[k])] = li[k];
    imp_ids_ = std::move(ids);
    ++stats_.step_solves;
    stats_.contact_points += rep.points;
    if (rep.ill_conditioned > 0) warn("ill_conditioned_solve", static_cast<std::uint64_t>(rep.ill_conditioned));
}

void NativeBackend::advanceBodies(const std::vector<BodyImpulse>& imp, double h, double t_next) {
    // Only bodies a contact impulse acted on move now; the others fly on lazily (syncBody).
    for (int id : imp_ids_) {
        const std::size_t i = static_cast<std::size_t>(id);
        RigidBody& rb = bodies_[i];
        if (rb.is_static || !imp[i].supported) continue;
        valid_at_[i] = t_next;
        const RigidBody saved = rb;
        if (imp[i].supported) {
            // Contact impulses act over the step: position by the mean velocity (exactly the
            // ballistic formula when the impulse is zero), rotation split half before, half after.
            const Vec3 v_end = rb.velocity + scene_.gravity * h + rb.inv_mass * imp[i].linear;
            rb.com += (0.5 * h) * (rb.velocity + v_end);
            rb.velocity = v_end;
            rb.angular_momentum += 0.5 * imp[i].angular;
            rb.refreshEnergy();
            advanceTorqueFree(rb, h);
            rb.angular_momentum += 0.5 * imp[i].angular;
            rb.refreshEnergy();
            bumpVersion(static_cast<int>(i));
        }
        recoverIfNonFinite(static_cast<int>(i), saved);
    }
}

void NativeBackend::emitEvents(const std::vector<PairSample>& samples,
                               const std::vector<ContactManifold>& manifolds, double t) {
    // Per pair: total normal impulse of this step and its strongest manifold.
    std::map<int, std::pair<double, const ContactManifold*>> per_pair;
    for (const ContactManifold& m : manifolds) {
        auto& [sum, best] = per_pair[m.pair];
        const double j = m.collision_impulse + m.contact_impulse;
        if (best == nullptr || j > best->collision_impulse + best->contact_impulse) best = &m;
        sum += j;
    }
    for (const PairSample& s : samples) {
        if (s.manifolds.empty()) continue;
        const PairState& ps = pairs_[static_cast<std::size_t>(s.pair)];
        const bool was_touching = ps.touching && ps.touching_step == step_index_ - 1;
        const auto it = per_pair.find(s.pair);
        if (was_touching || it == per_pair.end() || !(it->second.first > 0.0)) continue;
        CollisionEvent e;
        e.time = t;
        e.body_a = ps.a;
        e.body_b = ps.b;
        e.point = it->second.second->centroid;
        e.normal = it->second.second->normal;
        e.impulse = it->second.first;
        events_.push_back(e);
        ++stats_.collisions;
    }
}

void NativeBackend::recoverIfNonFinite(int body, const RigidBody& saved) {
    RigidBody& rb = bodies_[static_cast<std::size_t>(body)];
    if (rb.com.allFinite() && rb.velocity.allFinite() && rb.angular_momentum.allFinite() &&
        rb.orientation.coeffs().allFinite())
        return;
    warn("nonfinite_state");
    rb = saved;
    rb.velocity.setZero();
    rb.angular_momentum.setZero();
    rb.refreshEnergy();
    bumpVersion(body);
}

}  // namespace vroc::native
