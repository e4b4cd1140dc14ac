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

FreeFlight::FreeFlight() : scene(emptyScene()) {
    ball = addBall(scene, "ball", 0.1, 2.0, x0);
    scene.bodies[static_cast<std::size_t>(ball)].linear_velocity = v0;
}

}  // namespace vroc::test
