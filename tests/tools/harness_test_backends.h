// SPDX-License-Identifier: MIT
// Tiny backends for the harness tests, with trajectories known in closed form: "test-exact"
// (exact ballistic flight), "test-euler" (semi-implicit Euler: x_n = exact + g dt t / 2) and
// "test-dropping" (exact flight that counts one `contacts_dropped` a frame, as an engine whose
// buffer is full does: its runs are not valid).
// Neither handles contact; they exist so harness metrics can be checked against hand computation
// without depending on a real backend.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "vroc/core/backend.h"
#include "vroc/core/backend_registry.h"
#include "vroc/core/backend_vocabulary.h"
#include "vroc/core/mass_properties.h"
#include "vroc/harness/runs/backend_selection.h"

namespace vroc::harness_test {

class FlightBackend final : public Backend {
public:
    FlightBackend(const Scene& scene, bool exact, bool drops = false) : scene_(scene), exact_(exact), drops_(drops) {
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
        if (drops_) ++dropped_;
    }
    double time() const override { return time_; }
    int bodyCount() const override { return static_cast<int>(states_.size()); }
    BodyState bodyState(int body) const override { return states_[static_cast<std::size_t>(body)]; }
    void setBodyState(int body, const BodyState& state) override {
        if (!scene_.bodies[static_cast<std::size_t>(body)].isStatic()) states_[static_cast<std::size_t>(body)] = state;
    }
    void applyImpulse(int, const Vec3&, const Vec3&) override {}
    std::vector<CollisionEvent> takeEvents() override { return {}; }
    WarningCounts warnings() const override {
        return drops_ ? WarningCounts{{vocabulary::kContactsDropped, dropped_}} : WarningCounts{};
    }
    Statistics statistics() const override { return {{"bodies", static_cast<double>(states_.size())}}; }

private:
    Scene scene_;
    bool exact_;
    bool drops_;
    std::uint64_t dropped_ = 0;
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
    BackendInfo dropping = exact;
    dropping.name = "test-dropping";
    dropping.description = "exact flight that drops contacts every frame (tests only)";
    dropping.create = [](const Scene& s, const Settings&) -> std::unique_ptr<Backend> {
        return std::make_unique<FlightBackend>(s, true, true);
    };
    BackendRegistry::global().add(exact);
    BackendRegistry::global().add(euler);
    BackendRegistry::global().add(dropping);
}

/// A ball in free flight from 100 m up (frame 0.01 s, g = 10 m/s^2): x(t) in closed form.
inline Scene flightScene() {
    Scene s;
    s.name = "flight";
    s.gravity = Vec3(0, 0, -10);
    s.frame_dt = 0.01;
    s.materials.push_back({"m", 0.5, 0.5});
    Body b;
    b.name = "ball";
    b.shape = Shape::sphere(0.1);
    b.mass_properties = massProperties(b.shape, 2.0);
    b.pose.position = Vec3(0, 0, 100);
    b.linear_velocity = Vec3(1, 0, 3);
    s.bodies.push_back(b);
    return s;
}

/// The test backends of `list` (comma-separated), registered first.
inline std::vector<harness::SelectedBackend> testBackends(const std::string& list) {
    registerTestBackends();
    return harness::selectBackends(list, {});
}

}  // namespace vroc::harness_test
