// SPDX-License-Identifier: MIT
// Every shipped scene (scenes/*.json) loads and runs with Bullet: finite states, no warnings.
// Prints steps, wall time and per-frame p50 per scene, and the resting gap of hull_rest.json.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <limits>

#include "test_scenes.h"
#include "vroc/core/scene_loader.h"

namespace vroc::test {
namespace {

namespace fs = std::filesystem;

TEST(BulletScenes, EveryShippedSceneRunsCleanly) {
    const auto files = shippedSceneFiles();
    if (files.empty()) GTEST_SKIP() << "no scenes/*.json yet";
    std::printf("| scene | bodies | frames | wall s | p50 us/frame | events |\n|---|---|---|---|---|---|\n");
    for (const fs::path& file : files) {
        SCOPED_TRACE(file.string());
        const Scene scene = loadScene(file.string());
        auto backend = makeBullet(scene);
        const int frames = static_cast<int>(std::lround(3.0 / scene.frame_dt));
        const TimedRun run = timedRun(*backend, scene, frames);
        for (int i = 0; i < backend->bodyCount(); ++i) {
            const BodyState s = backend->bodyState(i);
            ASSERT_TRUE(s.pose.position.allFinite() && s.linear_velocity.allFinite() &&
                        s.angular_velocity.allFinite()) << "body " << scene.bodies[i].name;
        }
        for (const auto& [kind, count] : backend->warnings()) EXPECT_EQ(count, 0u) << kind;
        std::printf("| %s | %zu | %d | %.3f | %.1f | %zu |\n", file.filename().c_str(), scene.bodies.size(), frames,
                    run.totalSeconds(), run.quantileUs(0.5), run.events);
    }
}

TEST(BulletScenes, HullRestSettlesOnAFace) {
    const fs::path file = fs::path(VROC_SOURCE_DIR) / "scenes" / "hull_rest.json";
    if (!fs::exists(file)) GTEST_SKIP() << "no scenes/hull_rest.json yet";
    const Scene scene = loadScene(file.string());
    const int gem = scene.findBody("gem");
    ASSERT_GE(gem, 0);
    for (const char* shrink : {"true", "false"}) {
        auto backend = makeBullet(scene, {{"bullet.shrink_hulls", shrink}});
        for (int f = 0; f < 240; ++f) backend->stepFrame(scene.frame_dt);
        const BodyState s = backend->bodyState(gem);
        double lowest = std::numeric_limits<double>::infinity();
        for (const Vec3& v : scene.bodies[gem].shape.hull->vertices) lowest = std::min(lowest, s.pose.apply(v).z());
        std::printf("| hull_rest.json, shrink_hulls=%s | lowest vertex z after 4 s = %+.6f m | speed %.2e m/s |\n",
                    shrink, lowest, s.linear_velocity.norm());
        if (std::string(shrink) == "true") EXPECT_NEAR(lowest, 0.0, 2e-3);
        else EXPECT_NEAR(lowest, 0.04, 2e-3);   // plain Bullet: the default margin, 4 cm
    }
}

}  // namespace
}  // namespace vroc::test
