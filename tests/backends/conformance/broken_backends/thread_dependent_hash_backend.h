// SPDX-License-Identifier: MIT
// Broken on purpose: results depend on the worker count. With native.threads > 1, every frame
// ends with the first virtual body moved 1 nm along x, the size of a reduction summed in worker
// order. Default settings (one worker) are native's bits exactly, so only a check that varies the
// worker count sees it: rejected by checkWorkerCountDeterminism.
#pragma once

#include <memory>

#include "broken_backends/delegating_backend.h"

namespace vroc::conformance {

class ThreadDependentHashBackend : public DelegatingBackend {
public:
    /// `nudged`: the body moved after each frame (-1: none); `threads`: native.threads.
    ThreadDependentHashBackend(std::unique_ptr<Backend> inner, int nudged, int threads)
        : DelegatingBackend(std::move(inner)), nudged_(nudged), threads_(threads) {}

    void stepFrame(double dt) override {
        inner().stepFrame(dt);
        if (threads_ <= 1 || nudged_ < 0) return;
        BodyState s = inner().bodyState(nudged_);
        s.pose.position.x() += 1e-9;  // [m]
        inner().setBodyState(nudged_, s);
    }

private:
    int nudged_ = -1;
    int threads_ = 1;
};

inline BackendInfo threadDependentHashBackend() {
    return wrappedNativeInfo(
        "thread_dependent_hash", [](const Scene& scene, const Settings& settings) -> std::unique_ptr<Backend> {
            int nudged = -1;
            for (std::size_t i = 0; i < scene.bodies.size() && nudged < 0; ++i)
                if (scene.bodies[i].isDynamic()) nudged = static_cast<int>(i);
            return std::make_unique<ThreadDependentHashBackend>(nativeInfo().create(scene, settings), nudged,
                                                                static_cast<int>(settings.integer("native.threads")));
        });
}

}  // namespace vroc::conformance
