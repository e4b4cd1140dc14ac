// SPDX-License-Identifier: MIT
#include "test_scenes.h"

#include "vroc/mujoco/mujoco_backend.h"

namespace vroc::test {

std::unique_ptr<Backend> makeMujoco(const Scene& scene, const Overrides& overrides) {
    mujoco::registerBackend();
    return makeRegistered("mujoco", scene, overrides);
}

void run(Backend& backend, const Scene& scene, int frames) {
    for (int f = 0; f < frames; ++f) backend.stepFrame(scene.frame_dt);
}

}  // namespace vroc::test
