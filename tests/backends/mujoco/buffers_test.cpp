// SPDX-License-Identifier: MIT
// MuJoCo 2.2 allocates its contact list, constraint rows and scratch stack once. A step that
// overflows them is taken again with larger ones, so a pile of boxes loses no contact to the
// harness's sizing (issue 23): nine box pyramids used to drop hundreds of constraint rows in a
// quarter second, and 400 boxes in a bin overflowed the stack (mujoco.error) at every step.
#include <gtest/gtest.h>

#include "test_scenes.h"
#include "vroc/core/scene_loader.h"

namespace vroc::test {
namespace {

std::uint64_t warning(const Backend& b, const std::string& name) {
    const WarningCounts w = b.warnings();
    const auto it = w.find(name);
    return it == w.end() ? 0 : it->second;
}

// No contact or constraint row dropped and no stack overflow in any step so far.
void expectNothingDropped(const Backend& b) {
    EXPECT_EQ(warning(b, "mujoco.contact_full"), 0u);
    EXPECT_EQ(warning(b, "mujoco.constraint_full"), 0u);
    EXPECT_EQ(warning(b, "mujoco.error"), 0u);
    EXPECT_EQ(warning(b, "contacts_dropped"), 0u);  // the shared name the harness marks runs by
}

TEST(MujocoBuffers, NinePyramidsDropNoContactAndGrowTheirBuffers) {
    const Scene scene = loadScene(VROC_SOURCE_DIR "/scenes/stress/pyramids9_base6.json");
    auto backend = makeMujoco(scene);
    run(*backend, scene, 15);
    expectNothingDropped(*backend);
    const Statistics st = backend->statistics();
    EXPECT_GE(st.at("mujoco.buffer_growths"), 1.0);   // the first guess was too small: it grew
    // Every box is still on its pyramid (nothing fell through for a dropped contact).
    for (int i = 0; i < backend->bodyCount(); ++i) {
        if (scene.bodies[static_cast<std::size_t>(i)].isDynamic()) {
            EXPECT_GT(backend->bodyState(i).pose.position.z(), 0.0) << scene.bodies[static_cast<std::size_t>(i)].name;
        }
    }
}

TEST(MujocoBuffers, FourHundredBoxesInABinStepWithoutStackErrors) {
    const Scene scene = loadScene(VROC_SOURCE_DIR "/scenes/stress/bin_boxes400.json");
    auto backend = makeMujoco(scene);
    run(*backend, scene, 10);
    expectNothingDropped(*backend);
}

}  // namespace
}  // namespace vroc::test
