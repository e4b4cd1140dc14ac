// SPDX-License-Identifier: MIT
// Every shipped scene runs 3 s without warnings; prints wall time per frame (the baseline table of
// docs/mujoco-backend.md), and the hull_rest scene's lowest vertex.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "test_scenes.h"
#include "vroc/core/scene_loader.h"

namespace vroc::test {
namespace {

TEST(MujocoScenes, EveryShippedSceneRunsCleanly) {
    std::printf("| scene | bodies | frames | wall s | p50 us/frame | p90 us/frame | events |\n|---|---|---|---|---|---|---|\n");
    for (const char* name : {"ball_drop", "ball_drop_e1", "chair", "desk", "hull_rest", "notepad", "staircase"}) {
        const Scene scene = loadScene(std::string(VROC_SOURCE_DIR) + "/scenes/" + name + ".json");
        auto backend = makeMujoco(scene);
        const int frames = 180;
        const TimedRun run = timedRun(*backend, scene, frames);
        std::printf("| %s.json | %zu | %d | %.3f | %.1f | %.1f | %zu |\n", name, scene.bodies.size(), frames,
                    run.totalSeconds(), run.quantileUs(0.5), run.quantileUs(0.9), run.events);
        for (const auto& [warning, count] : backend->warnings()) EXPECT_EQ(count, 0u) << name << ": " << warning;
        for (int i = 0; i < backend->bodyCount(); ++i) {
            const BodyState s = backend->bodyState(i);
            EXPECT_TRUE(s.pose.position.allFinite() && s.linear_velocity.allFinite()) << name;
        }
    }
}

TEST(MujocoScenes, HullRestsOnItsLowestVertex) {
    const Scene scene = loadScene(std::string(VROC_SOURCE_DIR) + "/scenes/hull_rest.json");
    auto backend = makeMujoco(scene);
    run(*backend, scene, 240);
    for (int i = 0; i < backend->bodyCount(); ++i) {
        const Body& b = scene.bodies[static_cast<std::size_t>(i)];
        if (b.isStatic() || b.shape.kind != Shape::Kind::Hull) continue;
        const BodyState s = backend->bodyState(i);
        double lowest = 1e9;
        for (const Vec3& v : b.shape.hull->vertices) lowest = std::min(lowest, s.pose.apply(v).z());
        std::printf("hull_rest.json after 4 s: lowest vertex z = %+.6f m, speed %.2e m/s\n", lowest, s.linear_velocity.norm());
        // One contact point per mesh pair: the hull rocks on the floor (docs/mujoco-backend.md).
        EXPECT_NEAR(lowest, 0.0, 1e-3);
        EXPECT_LT(s.linear_velocity.norm(), 0.1);
    }
}

}  // namespace
}  // namespace vroc::test

namespace vroc::test {
namespace {

// MuJoCo re-centres a mesh at its centroid along its own principal axes and moves the geom frame
// to match; a hull whose vertices sit off the body origin (COM 4 cm up, axes turned 90 degrees)
// must still rest with its lowest vertex on the floor.
TEST(MujocoScenes, OffsetHullKeepsItsSurface) {
    Scene scene = emptyScene(0.0, 0.8);
    addFloor(scene);
    Pose pose;
    pose.position = Vec3(0, 0, 0.2);
    const Quat rot(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitX()));
    const int hull = addHullCuboid(scene, "hull", Vec3(0.1, 0.05, 0.08), 1.0, pose, rot, Vec3(0.03, -0.02, 0.04));
    auto backend = makeMujoco(scene);
    run(*backend, scene, 120);
    const BodyState s = backend->bodyState(hull);
    double lowest = 1e9;
    for (const Vec3& v : scene.bodies[hull].shape.hull->vertices) lowest = std::min(lowest, s.pose.apply(v).z());
    std::printf("offset hull after 2 s: lowest vertex z = %+.6f m\n", lowest);
    EXPECT_NEAR(lowest, 0.0, 1e-3);
}

}  // namespace
}  // namespace vroc::test
