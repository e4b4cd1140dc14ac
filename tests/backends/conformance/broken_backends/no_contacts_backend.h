// SPDX-License-Identifier: MIT
// Broken on purpose: bodies fall through the real world. Native runs a copy of the scene without
// its real bodies; those stay where the scene puts them (the contract's static bodies) and nothing
// ever touches them. Rejected by checkLanding (no event with the floor; the body falls through it).
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "broken_backends/delegating_backend.h"
#include "vroc/core/errors.h"

namespace vroc::conformance {

class NoContactsBackend : public DelegatingBackend {
public:
    /// `inner` runs `scene` less its real bodies; `inner_index[i]` is body i's index there (-1: real).
    NoContactsBackend(const Scene& scene, std::unique_ptr<Backend> inner, std::vector<int> inner_index)
        : DelegatingBackend(std::move(inner)), scene_(scene), inner_index_(std::move(inner_index)) {}

    int bodyCount() const override { return static_cast<int>(inner_index_.size()); }
    BodyState bodyState(int body) const override {
        if (const int i = innerIndex(body); i >= 0) return inner().bodyState(i);
        BodyState s;
        s.pose = scene_.bodies[static_cast<std::size_t>(body)].pose;
        return s;
    }
    void setBodyState(int body, const BodyState& state) override {
        if (const int i = innerIndex(body); i >= 0) inner().setBodyState(i, state);
    }
    void applyImpulse(int body, const Vec3& impulse, const Vec3& world_point) override {
        if (const int i = innerIndex(body); i >= 0) inner().applyImpulse(i, impulse, world_point);
    }
    std::vector<CollisionEvent> takeEvents() override {
        std::vector<CollisionEvent> events = inner().takeEvents();
        for (CollisionEvent& e : events) e.body_a = outerIndex(e.body_a), e.body_b = outerIndex(e.body_b);
        return events;
    }

private:
    int innerIndex(int body) const {
        if (body < 0 || body >= bodyCount())
            throw InputError("no_contacts: body index " + std::to_string(body) + " out of range");
        return inner_index_[static_cast<std::size_t>(body)];
    }
    int outerIndex(int inner_body) const {
        for (std::size_t i = 0; i < inner_index_.size(); ++i)
            if (inner_index_[i] == inner_body) return static_cast<int>(i);
        return -1;
    }

    Scene scene_;
    std::vector<int> inner_index_;
};

/// Native on `scene` less its real bodies, behind the scene's indices.
inline std::unique_ptr<Backend> createNoContacts(const Scene& scene, const Settings& settings) {
    Scene unreal = scene;
    unreal.bodies.clear();
    std::vector<int> inner_index;
    for (const Body& b : scene.bodies) {
        inner_index.push_back(b.isStatic() ? -1 : static_cast<int>(unreal.bodies.size()));
        if (!b.isStatic()) unreal.bodies.push_back(b);
    }
    return std::make_unique<NoContactsBackend>(scene, nativeInfo().create(unreal, settings), std::move(inner_index));
}

inline BackendInfo noContactsBackend() { return wrappedNativeInfo("no_contacts", &createNoContacts); }

}  // namespace vroc::conformance
