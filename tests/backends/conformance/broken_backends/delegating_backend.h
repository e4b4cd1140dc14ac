// SPDX-License-Identifier: MIT
// The base of the broken backends: every call goes to a real backend (the native one, always
// built), so that a broken backend differs from a conforming one only in the call it overrides.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "conformance_backends.h"
#include "vroc/core/backend.h"

namespace vroc::conformance {

class DelegatingBackend : public Backend {
public:
    explicit DelegatingBackend(std::unique_ptr<Backend> inner) : inner_(std::move(inner)) {}

    void stepFrame(double dt) override { inner_->stepFrame(dt); }
    double time() const override { return inner_->time(); }
    int bodyCount() const override { return inner_->bodyCount(); }
    BodyState bodyState(int body) const override { return inner_->bodyState(body); }
    void setBodyState(int body, const BodyState& state) override { inner_->setBodyState(body, state); }
    void applyImpulse(int body, const Vec3& impulse, const Vec3& world_point) override {
        inner_->applyImpulse(body, impulse, world_point);
    }
    std::vector<CollisionEvent> takeEvents() override { return inner_->takeEvents(); }
    WarningCounts warnings() const override { return inner_->warnings(); }
    Statistics statistics() const override { return inner_->statistics(); }

protected:
    Backend& inner() { return *inner_; }
    const Backend& inner() const { return *inner_; }

private:
    std::unique_ptr<Backend> inner_;  ///< owned
};

/// The native backend's registration, the one every broken backend wraps.
inline const BackendInfo& nativeInfo() { return registeredBackend("native"); }

/// nativeInfo() renamed `name`, creating through `create`: a broken backend's BackendInfo.
inline BackendInfo wrappedNativeInfo(const std::string& name,
                                     std::unique_ptr<Backend> (*create)(const Scene&, const Settings&)) {
    BackendInfo info = nativeInfo();
    info.name = name;
    info.description = "test double: the native backend with one thing broken";
    info.create = create;
    return info;
}

}  // namespace vroc::conformance
