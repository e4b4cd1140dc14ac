// SPDX-License-Identifier: MIT
#include "vroc/play/grab_controller.h"

#include <limits>

namespace vroc::play {

GrabController::GrabController(const Scene& scene, const GrabSettings& settings)
    : scene_(scene), settings_(settings), estimator_(settings.velocity_window, settings.velocity_degree) {}

std::optional<int> GrabController::nearestBody(const Pose& hand, const Backend& backend) const {
    std::optional<int> best;
    double best_gap = std::numeric_limits<double>::infinity();
    for (int b = 0; b < backend.bodyCount(); ++b) {
        const Body& body = scene_.bodies[b];
        if (body.isStatic()) continue;
        const double gap = (backend.bodyState(b).pose.position - hand.position).norm() - body.shape.boundingRadius();
        if (gap <= settings_.reach && gap < best_gap) {   // ties: the lower index (determinism)
            best_gap = gap;
            best = b;
        }
    }
    return best;
}

BodyState GrabController::heldState(const Pose& hand) const {
    BodyState s;
    s.pose = hand * offset_;
    const Vec3 v = estimator_.linearVelocity();
    const Vec3 w = estimator_.angularVelocity();
    // Rigid motion with the hand: the centre of mass moves with v + w x (com - hand).
    const Vec3 com = s.pose.apply(com_local_);
    s.linear_velocity = v + w.cross(com - hand.position);
    s.angular_velocity = w;
    return s;
}

void GrabController::update(double t, const Pose& hand, bool button_down, Backend& backend,
                            const Vec3* device_linear, const Vec3* device_angular) {
    estimator_.add(t, hand);
    const bool pressed = button_down && !was_down_;
    const bool released = !button_down && was_down_;
    was_down_ = button_down;
    if (pressed && !held_) {
        held_ = nearestBody(hand, backend);
        if (held_) {
            ++grabs_;
            offset_ = hand.inverse() * backend.bodyState(*held_).pose;
            com_local_ = scene_.bodies[*held_].mass_properties.center_of_mass;
        }
    }
    if (!held_) return;
    const BodyState state = heldState(hand);
    backend.setBodyState(*held_, state);
    if (released) {
        ThrowRecord r;
        r.time = t;
        r.body = *held_;
        r.linear_velocity = state.linear_velocity;
        r.angular_velocity = state.angular_velocity;
        r.hand_linear_velocity = estimator_.linearVelocity();
        if (device_linear && device_angular) {
            r.device_velocity_known = true;
            r.device_linear_velocity = *device_linear;
            r.device_angular_velocity = *device_angular;
        }
        throws_.push_back(r);
        held_.reset();
    }
}

}  // namespace vroc::play
