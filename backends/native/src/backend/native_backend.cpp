// SPDX-License-Identifier: MIT
// The frame loop: internal steps at event times (docs/native-scheduling.md, "A frame").
#include "backend/native_backend.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "scheduling/collision_time_bound.h"
#include "vroc/core/body_motion_checks.h"
#include "vroc/core/errors.h"

namespace vroc::native {

NativeBackend::NativeBackend(const Scene& scene, const NativeSettings& settings)
    : scene_(scene), settings_(settings) {
    if (!(scene.collision_distance > 0.0))
        throw InputError("scene '" + scene.name + "': collision_distance must be > 0 for the native backend");
    for (const Body& body : scene.bodies) {
        if (body.isTracked() && !hasFiniteMotion(body))
            throw InputError("scene '" + scene.name + "', tracked body '" + body.name +
                             "': expected a finite pose and finite velocities (its prescribed motion)");
        bodies_.push_back(RigidBody::fromScene(body));
        try {
            shapes_.push_back(BodyShape::fromScene(body.shape, bodies_.back().com_offset));
        } catch (const GeometryError& e) {
            throw InputError("scene '" + scene.name + "', body '" + body.name + "': " + e.what());
        }
        infinite_mass_.push_back(bodies_.back().infiniteMass());
    }
    const std::size_t n = bodies_.size();
    versions_.assign(n, 0);
    valid_at_.assign(n, 0.0);
    drift_until_.assign(n, 0.0);
    drift_acceleration_.assign(n, Vec3::Zero());
    drift_torque_.assign(n, Vec3::Zero());
    sub_stepped_.assign(n, SubSteppedDrift{});
    held_.assign(n, 0);
    tick_end_.assign(n, 0.0);
    box_dirty_.assign(n, 1);
    asleep_.assign(n, 0);
    still_since_.assign(n, 0.0);
    body_pairs_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const RigidBody& rb = bodies_[i];
        broad_phase_.addBody(shapes_[i].worldAabb(rb.framePose()).inflated(scene.collision_distance),
                             rb.infiniteMass());
    }
    partition_ = std::make_unique<PairPartition>(settings_.threads);
}

void NativeBackend::checkBody(int body, const char* call) const {
    if (body < 0 || body >= bodyCount())
        throw InputError(std::string("native: ") + call + ": no body with index " + std::to_string(body) + " (the scene has " +
                         std::to_string(bodyCount()) + ")");
}

BodyState NativeBackend::bodyState(int body) const {
    checkBody(body, "bodyState");
    const RigidBody& rb = bodies_[static_cast<std::size_t>(body)];
    BodyState s;
    s.pose = rb.framePose();
    s.linear_velocity = rb.velocity;
    s.angular_velocity = rb.angularVelocity();
    return s;
}

void NativeBackend::setBodyState(int body, const BodyState& state) {
    checkBody(body, "setBodyState");
    RigidBody& rb = bodies_[static_cast<std::size_t>(body)];
    if (rb.is_static) return;
    if (!state.pose.position.allFinite() || !state.pose.orientation.coeffs().allFinite() ||
        !state.linear_velocity.allFinite() || !state.angular_velocity.allFinite()) {
        warn("nonfinite_state");
        return;
    }
    if (state.pose.orientation.norm() == 0.0)
        throw InputError("native: setBodyState: body " + std::to_string(body) + ": expected a non-zero quaternion");
    rb.setFromState(state.pose, state.linear_velocity, state.angular_velocity);
    wake(body);
    endDrift(body);   // the drift was for the old state
}

void NativeBackend::applyImpulse(int body, const Vec3& impulse, const Vec3& world_point) {
    checkBody(body, "applyImpulse");
    RigidBody& rb = bodies_[static_cast<std::size_t>(body)];
    if (rb.infiniteMass()) return;
    if (!impulse.allFinite() || !world_point.allFinite()) {
        warn("nonfinite_state");
        return;
    }
    rb.applyImpulse(impulse, world_point);
    wake(body);
    endDrift(body);
}

std::vector<CollisionEvent> NativeBackend::takeEvents() {
    std::vector<CollisionEvent> out;
    out.swap(events_);
    return out;
}

void NativeBackend::stepFrame(double dt) {
    if (!(dt > 0.0) || !std::isfinite(dt))
        throw InputError("native: stepFrame: frame dt must be a positive finite number [s], got " + std::to_string(dt));
    if (fixedTicks(settings_.touching)) {
        stepFixed(dt);
        return;
    }
    const double frame_start = time_;
    frame_end_ = frame_start + dt;
    frame_dt_ = dt;
    // Every body is valid at the frame start here; its box is swept over the whole frame, and pairs
    // that entered the broad phase are due at once.
    std::vector<int>& entered = step_entered_;
    entered.clear();
    updateBroadPhase(true, entered);
    for (int p : entered) {
        const PairState& ps = pairs_[static_cast<std::size_t>(p)];
        queue_.push(p, ps.a, ps.b, frame_start);
    }
    // Absolute times, so every internal step starts strictly before the frame end.
    double t = frame_start;
    std::int64_t steps = 0;
    while (t < frame_end_) {
        const bool unbounded = steps >= settings_.max_internal_steps;
        if (unbounded) warn("internal_step_cap");
        const double h = internalStep(t, frame_end_ - t, unbounded);
        ++steps;
        t = (h >= frame_end_ - t) ? frame_end_ : t + h;
    }
    time_ = frame_end_;
    syncAllBodies(time_);
    ++stats_.frames;
    stats_.internal_steps += steps;
    stats_.max_internal_steps_per_frame = std::max(stats_.max_internal_steps_per_frame, steps);
}

double NativeBackend::internalStep(double t, double remaining, bool unbounded) {
    ++step_index_;
    // 1. Due flight pairs: the queue's pairs whose earliest contact time has come, and every pair
    //    of a body changed from outside (setBodyState, applyImpulse), whose island is due too.
    std::vector<int>& due = step_due_;
    due.clear();
    for (int body : changed_) {
        setTick(body, std::min(tick_end_[static_cast<std::size_t>(body)], t));
        for (int p : body_pairs_[static_cast<std::size_t>(body)])
            if (!pairs_[static_cast<std::size_t>(p)].touching) due.push_back(p);
    }
    changed_.clear();
    while (queue_.nextTime() <= t) due.push_back(queue_.pop()->pair);
    std::sort(due.begin(), due.end());
    due.erase(std::unique(due.begin(), due.end()), due.end());
    stats_.flight_pair_queries += static_cast<std::int64_t>(due.size());
    stats_.broad_phase_pairs += static_cast<std::int64_t>(candidates_.size());

    // 2. Narrow phase of the due pairs; islands with a new contact or a tick due are solved.
    std::vector<PairSample>& samples = step_samples_;
    samplePairs(due, t, samples);
    solveIslands(samples, t);
    recycleSamples(samples);

    // 3. Velocities changed: boxes and the changed bodies' flight pairs are bounded again now, with
    //    the new motion (a ball bouncing off the floor into a slab just above it is met in time).
    std::vector<int>& entered = step_entered_;
    entered.clear();
    updateBroadPhase(false, entered);
    std::vector<int>& again = step_again_;
    again.assign(entered.begin(), entered.end());
    for (int body : changed_)
        for (int p : body_pairs_[static_cast<std::size_t>(body)]) {
            const PairState& ps = pairs_[static_cast<std::size_t>(p)];
            if (!ps.touching && ps.sampled_step != step_index_) again.push_back(p);
        }
    changed_.clear();
    std::sort(again.begin(), again.end());
    again.erase(std::unique(again.begin(), again.end()), again.end());
    std::vector<PairSample>& resampled = step_resampled_;
    samplePairs(again, t, resampled);
    recordSamples(resampled);
    for (const PairSample& s : resampled) scheduleSampled(s, t, false);
    recycleSamples(resampled);

    if (unbounded) return remaining;
    const double h_min = std::min(remaining, 1e-9);
    double h = std::min(remaining, nextEventTime(t) - t);
    if (h < h_min) {
        warn("zeno_contact");
        h = h_min;
    }
    return h;
}

double NativeBackend::nextEventTime(double t) { return std::max(std::min(queue_.nextTime(), nextTick()), t); }

double NativeBackend::nextTick() {
    if (!ticks_dirty_) return next_tick_;
    ticks_dirty_ = false;
    next_tick_ = kNever;
    for (int p : touching_) {
        const PairState& ps = pairs_[static_cast<std::size_t>(p)];
        for (int body : {ps.a, ps.b})
            if (!infinite_mass_[static_cast<std::size_t>(body)])
                next_tick_ = std::min(next_tick_, tick_end_[static_cast<std::size_t>(body)]);
    }
    return next_tick_;
}

bool NativeBackend::finiteState(const RigidBody& rb) {
    return rb.com.allFinite() && rb.velocity.allFinite() && rb.angular_momentum.allFinite() &&
           rb.orientation.coeffs().allFinite();
}

void NativeBackend::recoverIfNonFinite(int body, const RigidBody& saved) {
    RigidBody& rb = bodies_[static_cast<std::size_t>(body)];
    if (finiteState(rb)) return;
    rb = saved;
    restNonFinite(body);
}

void NativeBackend::restNonFinite(int body) {
    RigidBody& rb = bodies_[static_cast<std::size_t>(body)];
    warn("nonfinite_state");
    rb.velocity.setZero();
    rb.angular_momentum.setZero();
    rb.refreshEnergy();
    endDrift(body);
}

}  // namespace vroc::native
