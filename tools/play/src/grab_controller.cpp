// SPDX-License-Identifier: MIT
#include "vroc/play/grab_controller.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "vroc/core/rotation_vector.h"

namespace vroc::play {

GrabController::GrabController(const Scene& scene, const GrabSettings& settings)
    : scene_(scene), settings_(settings), estimator_(settings.velocity_window, settings.velocity_degree) {
    if (!(settings.coupling_frequency > 0.0) || !std::isfinite(settings.coupling_frequency))
        throw std::invalid_argument("grab: coupling_frequency must be a positive number of Hz");
    if (!(settings.coupling_damping_ratio > 0.0) || !std::isfinite(settings.coupling_damping_ratio))
        throw std::invalid_argument("grab: coupling_damping_ratio must be positive");
    if (!(settings.coupling_stability_fraction > 0.0 && settings.coupling_stability_fraction < 1.0))
        throw std::invalid_argument("grab: coupling_stability_fraction must be in (0, 1)");
}

std::optional<int> GrabController::nearestBody(const Pose& hand, const Backend& backend) const {
    std::optional<int> best;
    double best_gap = std::numeric_limits<double>::infinity();
    for (int b = 0; b < backend.bodyCount(); ++b) {
        const Body& body = scene_.bodies[b];
        if (!body.isDynamic()) continue;   // real and tracked bodies are not ours to move
        const double gap = (backend.bodyState(b).pose.position - hand.position).norm() - body.shape.boundingRadius();
        if (gap <= settings_.reach && gap < best_gap) {   // ties: the lower index (determinism)
            best_gap = gap;
            best = b;
        }
    }
    return best;
}

double GrabController::couplingOmega(double dt) const {
    const double zeta = settings_.coupling_damping_ratio;
    // Largest w dt with b = 2 zeta w dt < 2 and a + 2b = (w dt)^2 + 4 zeta w dt < 4.
    const double limit = std::min(1.0 / zeta, 2.0 * (std::sqrt(zeta * zeta + 1.0) - zeta));
    return std::min(2.0 * std::numbers::pi * settings_.coupling_frequency,
                    settings_.coupling_stability_fraction * limit / dt);
}

void GrabController::couple(const HandInput& in, const BodyState& body, Backend& backend) {
    const int b = *held_;
    const double t = in.t, dt = in.dt;
    const Pose& hand = in.pose;
    const double zeta = settings_.coupling_damping_ratio;
    const double w = couplingOmega(dt);
    gains_ = {w, mass_ * w * w, 2.0 * zeta * mass_ * w};

    const Pose target = hand * offset_;
    const Vec3 x_target = target.apply(com_local_);
    const Vec3 x_body = body.pose.apply(com_local_);
    const Vec3 w_hand = estimator_.angularVelocity();
    const Vec3 v_target = estimator_.linearVelocity() + w_hand.cross(x_target - hand.position);
    // The body's mean velocity over the last frame, from its positions. In free flight it equals the
    // reported velocity without gravity; with the compensation impulse at the frame start it is what
    // the body really did, whichever way the backend integrates (exact flight or semi-implicit
    // Euler), so the damper sees no gravity bias and the body hangs exactly at the hand.
    const Vec3 v_body = (last_com_ && t > last_t_) ? Vec3((x_body - *last_com_) / (t - last_t_)) : body.linear_velocity;
    last_com_ = x_body;
    last_t_ = t;

    const Vec3 force = gains_.stiffness * (x_target - x_body) + gains_.damping * (v_target - v_body);
    const Mat3 r = body.pose.orientation.toRotationMatrix();
    const Mat3 inertia_world = r * inertia_ * r.transpose();
    const Vec3 theta = rotationVectorFromQuat(target.orientation * body.pose.orientation.conjugate());
    const Vec3 torque = inertia_world * (w * w * theta + 2.0 * zeta * w * (w_hand - body.angular_velocity));

    Vec3 impulse = force * dt;
    if (settings_.gravity_compensation) impulse -= mass_ * scene_.gravity * dt;
    const Vec3 angular = torque * dt;
    if (angular.squaredNorm() == 0.0) {
        backend.applyImpulse(b, impulse, x_body);
    } else {
        // The angular impulse as a couple: +-j at x_body +- u/2 with u a unit vector normal to it and
        // j = angular x u, so u x j = angular; each carries half the linear impulse.
        const Vec3 u = angular.unitOrthogonal();
        const Vec3 j = angular.cross(u);
        backend.applyImpulse(b, 0.5 * impulse + j, x_body + 0.5 * u);
        backend.applyImpulse(b, 0.5 * impulse - j, x_body - 0.5 * u);
    }
    wrench_.active = true;
    wrench_.force = -force;
    wrench_.torque = -torque + (x_target - hand.position).cross(-force);
}

void GrabController::update(const HandInput& in, Backend& backend) {
    if (!(in.dt > 0.0) || !std::isfinite(in.dt)) throw std::invalid_argument("grab: update needs a positive frame dt");
    const Pose& hand = in.pose;
    estimator_.add(in.sample_time.value_or(in.t), hand);
    wrench_ = {};
    const bool pressed = in.button && !was_down_;
    const bool released = !in.button && was_down_;
    was_down_ = in.button;
    if (pressed && !held_) {
        held_ = nearestBody(hand, backend);
        if (held_) {
            ++grabs_;
            const Body& body = scene_.bodies[*held_];
            offset_ = hand.inverse() * backend.bodyState(*held_).pose;
            com_local_ = body.mass_properties.center_of_mass;
            mass_ = body.mass_properties.mass;
            inertia_ = body.mass_properties.inertia;
            last_com_.reset();
        }
    }
    if (!held_) return;
    const BodyState state = backend.bodyState(*held_);
    if (released) {
        // The body leaves with the velocity the coupling gave it.
        ThrowRecord r;
        r.time = in.t;
        r.body = *held_;
        r.linear_velocity = state.linear_velocity;
        r.angular_velocity = state.angular_velocity;
        r.hand_linear_velocity = estimator_.linearVelocity();
        if (in.device_linear && in.device_angular) {
            r.device_velocity_known = true;
            r.device_linear_velocity = *in.device_linear;
            r.device_angular_velocity = *in.device_angular;
        }
        throws_.push_back(r);
        held_.reset();
        gains_ = {};
        return;
    }
    couple(in, state, backend);
}

}  // namespace vroc::play
