// SPDX-License-Identifier: MIT
#include "ballistic_backend.h"

#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "vroc/core/backend.h"
#include "vroc/core/backend_registry.h"
#include "vroc/core/backend_vocabulary.h"
#include "vroc/core/errors.h"
#include "vroc/core/rotation_vector.h"

namespace toy {
namespace {

using vroc::BodyState;
using vroc::Vec3;

// Each body keeps the state it had at its last set time t0, and its state at time t is evaluated
// from that in closed form, so no integration error accumulates: the centre of mass moves as
// c0 + v0 (t - t0) + g (t - t0)^2 / 2 (virtual bodies; tracked bodies without gravity), the
// orientation turns at the constant world angular velocity (exact for torque-free bodies with
// isotropic inertia, such as spheres). Real bodies never move.
class BallisticBackend final : public vroc::Backend {
public:
    explicit BallisticBackend(const vroc::Scene& scene) : gravity_(scene.gravity) {
        for (const vroc::Body& b : scene.bodies) {
            Flight f;
            f.role = b.role;
            if (b.isDynamic()) {
                f.com_body = b.mass_properties.center_of_mass;
                f.mass = b.mass_properties.mass;
                f.inertia_body = b.mass_properties.inertia;
            }
            f.start.pose = b.pose;
            f.start.linear_velocity = b.linear_velocity;
            f.start.angular_velocity = b.angular_velocity;
            bodies_.push_back(f);
        }
    }

    void stepFrame(double dt) override {
        if (!std::isfinite(dt) || dt <= 0.0) throw vroc::InputError("ballistic: frame dt must be finite and > 0");
        time_ += dt;
        ++frames_;
    }
    double time() const override { return time_; }
    int bodyCount() const override { return static_cast<int>(bodies_.size()); }

    BodyState bodyState(int body) const override {
        const Flight& f = at(body);
        if (f.role == vroc::BodyRole::Real) return f.start;
        const double t = time_ - f.t0;
        const Vec3 g = f.role == vroc::BodyRole::Virtual ? gravity_ : Vec3::Zero();
        BodyState out = f.start;
        const Vec3 c = f.start.pose.apply(f.com_body) + f.start.linear_velocity * t + 0.5 * g * t * t;
        out.pose.orientation =
            (vroc::quatFromRotationVector(f.start.angular_velocity * t) * f.start.pose.orientation).normalized();
        out.pose.position = c - out.pose.orientation * f.com_body;
        out.linear_velocity = f.start.linear_velocity + g * t;
        return out;
    }

    void setBodyState(int body, const BodyState& state) override {
        Flight& f = at(body);
        if (f.role == vroc::BodyRole::Real) return;
        if (!state.pose.position.allFinite() || !state.pose.orientation.coeffs().allFinite() ||
            !state.linear_velocity.allFinite() || !state.angular_velocity.allFinite()) {
            ++nonfinite_;   // the contract: counted and refused, the body unchanged
            return;
        }
        f.start = state;
        f.t0 = time_;
    }

    void applyImpulse(int body, const Vec3& impulse, const Vec3& world_point) override {
        Flight& f = at(body);
        if (f.role != vroc::BodyRole::Virtual) return;
        if (!impulse.allFinite() || !world_point.allFinite()) {
            ++nonfinite_;
            return;
        }
        BodyState now = bodyState(body);
        const vroc::Mat3 r = now.pose.orientation.toRotationMatrix();
        const Vec3 arm = world_point - now.pose.apply(f.com_body);
        now.linear_velocity += impulse / f.mass;
        now.angular_velocity += (r * f.inertia_body * r.transpose()).inverse() * arm.cross(impulse);
        setBodyState(body, now);
    }

    std::vector<vroc::CollisionEvent> takeEvents() override { return {}; }
    vroc::WarningCounts warnings() const override {
        if (nonfinite_ == 0) return {};
        return {{vroc::vocabulary::kNonfiniteState, nonfinite_}};
    }
    vroc::Statistics statistics() const override {
        return {{vroc::vocabulary::kFrames, static_cast<double>(frames_)},
                {vroc::vocabulary::kInternalSteps, static_cast<double>(frames_)},
                {vroc::vocabulary::kCollisionEvents, 0.0}};
    }

private:
    struct Flight {
        vroc::BodyRole role = vroc::BodyRole::Virtual;
        Vec3 com_body = Vec3::Zero();                  // [m] centre of mass, body frame
        double mass = 0.0;                             // [kg]
        vroc::Mat3 inertia_body = vroc::Mat3::Zero();  // [kg m^2] about the centre of mass, body axes
        BodyState start;                               // at time t0
        double t0 = 0.0;                               // [s]
    };

    const Flight& at(int body) const {
        if (body < 0 || body >= bodyCount()) throw vroc::InputError("ballistic: body index out of range");
        return bodies_[static_cast<std::size_t>(body)];
    }
    Flight& at(int body) { return const_cast<Flight&>(static_cast<const BallisticBackend*>(this)->at(body)); }

    Vec3 gravity_;
    std::vector<Flight> bodies_;
    double time_ = 0.0;
    std::int64_t frames_ = 0;
    std::uint64_t nonfinite_ = 0;
};

}  // namespace

void registerBallisticBackend() {
    vroc::BackendInfo info;
    info.name = "ballistic";
    info.description = "toy downstream backend: closed-form flight under gravity, no collisions";
    info.version = "ballistic 1.0";
    vroc::BackendCapabilities& c = info.capabilities;
    c.sphere = c.box = c.hull = c.compound = vroc::Support::Exact;
    c.tracked = vroc::Support::Exact;
    c.restitution = vroc::Support::Approximated;
    c.notes["restitution"] = "no collisions at all: bodies pass through each other and the real world";
    info.create = [](const vroc::Scene& scene, const vroc::Settings&) -> std::unique_ptr<vroc::Backend> {
        return std::make_unique<BallisticBackend>(scene);
    };
    vroc::BackendRegistry::global().add(std::move(info));
}

}  // namespace toy
