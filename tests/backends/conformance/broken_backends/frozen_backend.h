// SPDX-License-Identifier: MIT
// Broken on purpose: bodies never move. stepFrame counts the time and does nothing else; every
// other call is native's. Rejected by checkShippedScenes (a kicked body never rises) and
// checkLanding (a dropped body never lands).
#pragma once

#include <cmath>
#include <memory>

#include "broken_backends/delegating_backend.h"
#include "vroc/core/errors.h"

namespace vroc::conformance {

class FrozenBackend : public DelegatingBackend {
public:
    using DelegatingBackend::DelegatingBackend;

    void stepFrame(double dt) override {
        if (!(dt > 0.0) || !std::isfinite(dt)) throw InputError("frozen: a frame dt must be a positive finite number");
        time_ += dt;
    }
    double time() const override { return time_; }

private:
    double time_ = 0.0;  ///< [s]
};

inline BackendInfo frozenBackend() {
    return wrappedNativeInfo("frozen", [](const Scene& scene, const Settings& settings) -> std::unique_ptr<Backend> {
        return std::make_unique<FrozenBackend>(nativeInfo().create(scene, settings));
    });
}

}  // namespace vroc::conformance
