// SPDX-License-Identifier: MIT
// Broken on purpose: applyImpulse reads the impulse's components in the body frame (it applies
// R J for the body's orientation R instead of J), the mistake a backend makes when it hands a
// world vector to an engine call that expects body coordinates. Invisible on a body at identity
// orientation; rejected by checkImpulse, whose body is turned 0.7 rad.
#pragma once

#include <memory>

#include "broken_backends/delegating_backend.h"

namespace vroc::conformance {

class WrongFrameImpulseBackend : public DelegatingBackend {
public:
    using DelegatingBackend::DelegatingBackend;

    void applyImpulse(int body, const Vec3& impulse, const Vec3& world_point) override {
        const Quat body_to_world = inner().bodyState(body).pose.orientation;
        inner().applyImpulse(body, body_to_world * impulse, world_point);
    }
};

inline BackendInfo wrongFrameImpulseBackend() {
    return wrappedNativeInfo(
        "wrong_frame_impulse", [](const Scene& scene, const Settings& settings) -> std::unique_ptr<Backend> {
            return std::make_unique<WrongFrameImpulseBackend>(nativeInfo().create(scene, settings));
        });
}

}  // namespace vroc::conformance
