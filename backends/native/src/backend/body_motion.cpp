// SPDX-License-Identifier: MIT
// How bodies move between events. A body is valid at its own time (valid_at_) and brought forward
// lazily, only when a pair, an island or the frame end needs it. Two kinds of motion:
//   - free flight: gravity in closed form, torque-free rotation (exact);
//   - drift: after its island's contact phase, until the island's next tick, gravity and the contact
//     impulses act as constant force and torque over the tick (impulse / tick length): the COM flies
//     a parabola that ends the tick at the solved velocity, having moved with the mean of the start
//     and end velocities (exactly the ballistic path when no impulse acted). An island solved again
//     before its tick ends takes the state of that instant.
#include <algorithm>

#include "backend/native_backend.h"
#include "dynamics/free_flight.h"
#include "scheduling/collision_time_bound.h"
#include "vroc/core/rotation_vector.h"

namespace vroc::native {

void NativeBackend::syncBody(int body, double t) {
    if (!advanceBody(body, t)) restNonFinite(body);
}

void NativeBackend::syncAllBodies(double t) {
    // Every body on its own: the workers share them out, and a body whose state went non-finite
    // is put to rest (with its warning) after, in body order.
    constexpr std::size_t kBodyShare = 64;
    sync_failed_.assign(bodies_.size(), 0);
    partition_->forEachShared(bodies_.size(), kBodyShare, [this, t](std::size_t i) {
        if (!advanceBody(static_cast<int>(i), t)) sync_failed_[i] = 1;
    });
    for (std::size_t i = 0; i < bodies_.size(); ++i)
        if (sync_failed_[i] != 0) restNonFinite(static_cast<int>(i));
}

bool NativeBackend::advanceBody(int body, double t) {
    const std::size_t i = static_cast<std::size_t>(body);
    if (!(valid_at_[i] < t)) return true;
    double from = valid_at_[i];
    valid_at_[i] = t;
    RigidBody& rb = bodies_[i];
    if (rb.is_static || asleep_[i] != 0) return true;
    const RigidBody saved = rb;
    if (drift_until_[i] > from) {
        const double tau = std::min(t, drift_until_[i]) - from;
        const Vec3& a = drift_acceleration_[i];
        rb.com += rb.velocity * tau + (0.5 * tau * tau) * a;
        rb.velocity += a * tau;
        SubSteppedDrift& sub = sub_stepped_[i];
        if (sub.active) {
            // About a fixed axis: pieces of the turn compose to the whole, whatever the times.
            rb.orientation = (quatFromRotationVector(tau * sub.angular_velocity) * rb.orientation).normalized();
            rb.setAngularVelocity(sub.angular_velocity);
        } else {
            // The torque's impulse half before and half after the rotation (symmetric in time).
            rb.angular_momentum += (0.5 * tau) * drift_torque_[i];
            rb.refreshEnergy();
            advanceTorqueFree(rb, tau);
            rb.angular_momentum += (0.5 * tau) * drift_torque_[i];
            rb.refreshEnergy();
        }
        from += tau;
        if (sub.active && !(from < drift_until_[i])) {
            sub.active = false;
            rb.velocity = sub.end_velocity;
            rb.setAngularVelocity(sub.end_angular_velocity);
        }
    }
    if (t > from) {
        advanceBallistic(rb, t - from, scene_.gravity);
        advanceTorqueFree(rb, t - from);
    }
    if (finiteState(rb)) return true;
    rb = saved;
    return false;
}

MotionBound NativeBackend::ballisticBound(int body) const {
    const RigidBody& rb = bodies_[static_cast<std::size_t>(body)];
    if (rb.is_static || asleep_[static_cast<std::size_t>(body)] != 0) return MotionBound::stationary();
    MotionBound m;
    m.velocity = rb.velocity;
    m.acceleration = rb.is_kinematic ? Vec3::Zero() : scene_.gravity;
    m.angular_speed = rb.maxAngularSpeed();
    m.outer_radius = shapes_[static_cast<std::size_t>(body)].outer_radius;
    m.inner_radius = shapes_[static_cast<std::size_t>(body)].inner_radius;
    return m;
}

MotionBound NativeBackend::motionBound(int body, double& valid_until) const {
    const std::size_t i = static_cast<std::size_t>(body);
    valid_until = kNever;
    MotionBound m = ballisticBound(body);
    const RigidBody& rb = bodies_[i];
    if (rb.is_static || asleep_[i] != 0 || !(drift_until_[i] > valid_at_[i])) return m;
    valid_until = drift_until_[i];
    m.acceleration = drift_acceleration_[i];
    // |L| grows by at most |torque| t over the drift: |omega| is bounded by its largest value.
    if (rb.smallestMoment() > 0.0)
        m.angular_speed = (rb.angular_momentum.norm() + drift_torque_[i].norm() * (drift_until_[i] - valid_at_[i])) /
                          rb.smallestMoment();
    return m;
}

std::optional<RigidMotion> NativeBackend::rigidMotion(int body, double t, double duration) const {
    const std::size_t i = static_cast<std::size_t>(body);
    const RigidBody& rb = bodies_[i];
    if (rb.is_static || asleep_[i] != 0) return RigidMotion::stationary(rb.com);
    if (valid_at_[i] != t) return std::nullopt;
    const bool drifting = drift_until_[i] > valid_at_[i];
    RigidMotion m;
    m.com = rb.com;
    m.velocity = rb.velocity;
    m.acceleration = drifting ? drift_acceleration_[i] : (rb.is_kinematic ? Vec3::Zero() : scene_.gravity);
    m.angular_velocity = rb.angularVelocity();
    m.curvature = rotationCurvatureBound(rb.angular_momentum.norm(), drifting ? drift_torque_[i].norm() : 0.0,
                                         rb.smallestMoment(), duration, rb.isotropic);
    return m;
}

Aabb NativeBackend::sweptBox(int body) const {
    const std::size_t i = static_cast<std::size_t>(body);
    const RigidBody& rb = bodies_[i];
    const double r = shapes_[i].outer_radius;
    const Aabb now{rb.com - Vec3::Constant(r), rb.com + Vec3::Constant(r)};
    double until = kNever;
    const MotionBound m = motionBound(body, until);
    if (!(until < kNever)) return m.sweptAabb(now, std::max(0.0, frame_end_ - valid_at_[i])).inflated(scene_.collision_distance);
    // Drifting: the drift, then free flight to the frame end.
    const double tau = std::max(0.0, std::min(until, frame_end_) - valid_at_[i]);
    Aabb box = m.sweptAabb(now, tau);
    const double rest = frame_end_ - until;
    if (rest > 0.0) {
        const Vec3 c = rb.com + rb.velocity * tau + (0.5 * tau * tau) * drift_acceleration_[i];
        MotionBound after = ballisticBound(body);
        const SubSteppedDrift& sub = sub_stepped_[i];
        after.velocity = sub.active ? sub.end_velocity : Vec3(rb.velocity + drift_acceleration_[i] * tau);
        after.angular_speed = sub.active ? std::max(m.angular_speed, sub.end_angular_velocity.norm()) : m.angular_speed;
        const Aabb later = after.sweptAabb({c - Vec3::Constant(r), c + Vec3::Constant(r)}, rest);
        box.lower = box.lower.cwiseMin(later.lower);
        box.upper = box.upper.cwiseMax(later.upper);
    }
    return box.inflated(scene_.collision_distance);
}

bool NativeBackend::impactingContact(int body, const BodyImpulse& imp, double h) const {
    const RigidBody& rb = bodies_[static_cast<std::size_t>(body)];
    // The change over the tick: gravity's and the contact's. A supported body's cancel.
    return changedFaster(scene_.gravity * h + rb.inv_mass * imp.linear, rb.invInertiaWorld() * imp.angular, body, h);
}

void NativeBackend::applyContactImpact(int body, const BodyImpulse& imp) {
    const auto i = static_cast<std::size_t>(body);
    RigidBody& rb = bodies_[i];
    const RigidBody saved = rb;
    rb.com += imp.displacement;
    rb.velocity += rb.inv_mass * imp.linear;
    rb.angular_momentum += imp.angular;
    rb.refreshEnergy();
    endDrift(body);
    recoverIfNonFinite(body, saved);
}

void NativeBackend::startDrift(int body, const BodyImpulse& imp, double t, double h) {
    const std::size_t i = static_cast<std::size_t>(body);
    RigidBody& rb = bodies_[i];
    if (rb.infiniteMass() || !(h > 0.0)) return;
    const RigidBody saved = rb;
    // Split-impulse position correction: applied to the pose, never to the velocities.
    rb.com += imp.displacement;
    SubSteppedDrift& sub = sub_stepped_[i];
    sub.active = imp.sub_stepped;
    if (imp.sub_stepped) {
        // A straight path and a turn about a fixed axis at the sub-steps' mean velocities, then
        // their end velocities.
        rb.velocity = imp.mean_velocity;
        rb.setAngularVelocity(imp.mean_angular_velocity);
        drift_acceleration_[i] = Vec3::Zero();
        drift_torque_[i] = Vec3::Zero();
        sub.angular_velocity = imp.mean_angular_velocity;
        sub.end_velocity = imp.end_velocity;
        sub.end_angular_velocity = imp.end_angular_velocity;
    } else {
        drift_acceleration_[i] = scene_.gravity + (rb.inv_mass / h) * imp.linear;
        drift_torque_[i] = imp.angular / h;
    }
    valid_at_[i] = t;
    drift_until_[i] = t + h;
    held_[i] = 1;
    bumpVersion(body);
    recoverIfNonFinite(body, saved);
}

bool NativeBackend::touchesMovingTracked(int body) const {
    for (int p : body_pairs_[static_cast<std::size_t>(body)]) {
        if (!pairs_[static_cast<std::size_t>(p)].touching) continue;
        const PairState& ps = pairs_[static_cast<std::size_t>(p)];
        const RigidBody& other = bodies_[static_cast<std::size_t>(ps.a == body ? ps.b : ps.a)];
        if (other.is_kinematic && (!other.velocity.isZero(0.0) || !other.kinematic_angular_velocity.isZero(0.0)))
            return true;
    }
    return false;
}

void NativeBackend::maybeSleep(const std::vector<int>& island, double t) {
    if (!settings_.sleeping) return;
    bool all_still = true;
    for (int body : island) {
        const std::size_t i = static_cast<std::size_t>(body);
        if (infinite_mass_[i]) continue;
        if (touchesMovingTracked(body)) return;   // carried by a moving real object: never asleep
        const RigidBody& rb = bodies_[i];
        const double speed = rb.velocity.norm() + rb.angularVelocity().norm() * shapes_[i].outer_radius;
        if (!(speed < settings_.sleep_speed)) still_since_[i] = t;
        if (!(t - still_since_[i] >= settings_.sleep_time)) all_still = false;
    }
    if (!all_still) return;
    for (int body : island) {
        const std::size_t i = static_cast<std::size_t>(body);
        if (infinite_mass_[i]) continue;
        syncBody(body, t);
        RigidBody& rb = bodies_[i];
        rb.velocity.setZero();
        rb.angular_momentum.setZero();
        rb.refreshEnergy();
        asleep_[i] = 1;
        setTick(body, kNever);
        endDrift(body);
    }
    ++stats_.islands_slept;
}

}  // namespace vroc::native
