// SPDX-License-Identifier: MIT
// Two tiny backends for the harness tests, with trajectories known in closed form: "test-exact"
// (exact ballistic flight) and "test-euler" (semi-implicit Euler: x_n = exact + g dt t / 2).
// Neither handles contact; they exist so harness metrics can be checked against hand computation
// without depending on a real backend.
#pragma once

#include <memory>

#include "vroc/core/backend.h"
#include "vroc/core/backend_registry.h"

namespace vroc::harness_test {

class FlightBackend final : public Backend {
public:
    FlightBackend(const Scene& scene, bool exact) : scene_(scene), exact_(exact) {
        for (const Body& b : scene.bodies) states_.push_back({b.pose, b.linear_velocity, b.angular_velocity});
    }
    void stepFrame(double dt) override {
        for (std::size_t i = 0; i < states_.size(); ++i) {
            if (scene_.bodies[i].isStatic()) continue;
            BodyState& s = states_[i];
            if (exact_) {
                s.pose.position += s.linear_velocity * dt + 0.5 * scene_.gravity * dt * dt;
                s.linear_velocity += scene_.gravity * dt;
            } else {
                s.linear_velocity += scene_.gravity * dt;
                s.pose.position += s.linear_velocity * dt;
            }
            const double w = s.angular_velocity.norm();
            if (w > 0) s.pose.orientation = (Quat(Eigen::AngleAxisd(w * dt, s.angular_velocity / w)) * s.pose.orientation).normalized();
        }
        time_ += dt;
    }
    double time() const override { return time_; }
    int bodyCount() const override { return static_cast<int>(states_.size()); }
    BodyState bodyState(int body) const override { return states_[static_cast<std::size_t>(body)]; }
    void setBodyState(int body, const BodyState& state) override {
        if (!scene_.bodies[static_cast<std::size_t>(body)].isStatic()) states_[static_cast<std::size_t>(body)] = state;
    }
    void applyImpulse(int, const Vec3&, const Vec3&) override {}
    std::vector<CollisionEvent> takeEvents() override { return {}; }
    WarningCounts warnings() const override { return {}; }
    Statistics statistics() const override { return {{"bodies", static_cast<double>(states_.size())}}; }

private:
    Scene scene_;
    bool exact_;
    std::vector<BodyState> states_;
    double time_ = 0;
};

/// Registers test-exact and test-euler once.
inline void registerTestBackends() {
    static bool done = false;
    if (done) return;
    done = true;
    // Flight only: every shape "exact" (they ignore contact), so the harness runs every scene.
    BackendCapabilities flight;
    flight.sphere = flight.box = flight.hull = flight.compound = flight.restitution = Support::Exact;
    BackendInfo exact;
    exact.name = "test-exact";
    exact.description = "exact ballistic flight (tests only)";
    exact.version = "test 1";
    exact.capabilities = flight;
    exact.create = [](const Scene& s, const Settings&) -> std::unique_ptr<Backend> { return std::make_unique<FlightBackend>(s, true); };
    BackendInfo euler = exact;
    euler.name = "test-euler";
    euler.description = "semi-implicit Euler flight (tests only)";
    euler.create = [](const Scene& s, const Settings&) -> std::unique_ptr<Backend> { return std::make_unique<FlightBackend>(s, false); };
    BackendRegistry::global().add(exact);
    BackendRegistry::global().add(euler);
}

}  // namespace vroc::harness_test
