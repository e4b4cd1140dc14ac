// SPDX-License-Identifier: MIT
// The Bullet reference's own accuracy and cost, printed as the tables of docs/bullet-backend.md
// (run: build-*/bin/vroc_bullet_tests --gtest_filter='BulletBaseline.*'). The assertions are
// loose bounds around the closed forms; the printed numbers are the baseline.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "test_scenes.h"

namespace vroc::test {
namespace {

DropResult ballDrop(double e, const Overrides& overrides, int count) {
    return test::ballDrop(&makeBullet, e, overrides, count);
}

std::vector<double> apexes(double e, const Overrides& overrides, int count) {
    return ballDrop(e, overrides, count).apexes;
}

void printApexTable(double e, const char* label, const Overrides& overrides) {
    printApexRow(e, label, ballDrop(e, overrides, 5));
}

TEST(BulletBaseline, BallDropApexes) {
    std::printf("| e | settings | events | apex 1 | apex 2 | apex 3 | apex 4 | apex 5 |\n"
                "|---|---|---|---|---|---|---|---|\n");
    std::printf("| 0.5 | ideal e^(2n) h | 5 | 0.2500 | 0.0625 | 0.0156 | 0.0039 | 0.0010 |\n");
    const Overrides recipe = {{"bullet.restitution_threshold", "0"}, {"bullet.warmstarting_factor", "0"}};
    for (double e : {0.5, 1.0}) {
        printApexTable(e, "defaults (substeps 1, 60 Hz)", {});
        printApexTable(e, "substeps 4", {{"bullet.substeps", "4"}});
        printApexTable(e, "substeps 16", {{"bullet.substeps", "16"}});
        printApexTable(e, "threshold 0, warm start 0", recipe);
        printApexTable(e, "split impulse off", {{"bullet.split_impulse", "false"}});
        printApexTable(e, "ccd off", {{"bullet.ccd", "false"}});
        printApexTable(e, "substeps 1, threshold 0, warm start 0",
                       {{"bullet.substeps", "1"}, recipe[0], recipe[1]});
    }
    // Loose sanity bounds: the first apex is within 50 % of e^2 h with the defaults.
    for (double e : {0.5, 1.0}) {
        const auto a = apexes(e, {}, 1);
        ASSERT_EQ(a.size(), 1u);
        EXPECT_NEAR(a[0], e * e, 0.5 * e * e) << "e=" << e;
    }
}

double restingGap(const Shape& shape, const Overrides& overrides) {
    Scene scene = emptyScene(0.0, 0.5);
    addFloor(scene);
    Body b;
    b.name = "cube";
    b.shape = shape;
    b.pose.position = Vec3(0, 0, 0.12);
    b.mass_properties.mass = 1.0;
    b.mass_properties.inertia = cuboidInertia(Vec3(0.1, 0.1, 0.1), 1.0);
    scene.bodies.push_back(b);
    auto backend = makeBullet(scene, overrides);
    for (int f = 0; f < 120; ++f) backend->stepFrame(scene.frame_dt);
    return backend->bodyState(1).pose.position.z() - 0.1;
}

TEST(BulletBaseline, RestingGapOfACube) {
    const Shape hull = Shape::convexHull(cuboidHull(Vec3(0.1, 0.1, 0.1)));
    const Shape box = Shape::box(Vec3(0.1, 0.1, 0.1));
    struct Row { const char* label; Shape shape; Overrides o; };
    const Row rows[] = {
        {"hull, defaults (shrink on, margin 0.04)", hull, {}},
        {"hull, shrink on, margin 0.01", hull, {{"bullet.margin", "0.01"}}},
        {"hull, shrink off, margin 0.04 (plain Bullet)", hull, {{"bullet.shrink_hulls", "false"}}},
        {"hull, shrink off, margin 0.01", hull, {{"bullet.shrink_hulls", "false"}, {"bullet.margin", "0.01"}}},
        {"hull, shrink off, margin 0", hull, {{"bullet.shrink_hulls", "false"}, {"bullet.margin", "0"}}},
        {"box (btBoxShape), margin 0.04", box, {}},
    };
    std::printf("| 0.2 m cube after 2 s | gap (m) |\n|---|---|\n");
    for (const Row& r : rows) std::printf("| %s | %+.6f |\n", r.label, restingGap(r.shape, r.o));
    EXPECT_NEAR(restingGap(hull, {}), 0.0, 1e-3);
}

struct Percentiles { double p50, p90, p99; };

Percentiles frameTimes(const Scene& scene, int frames) {
    auto backend = makeBullet(scene);
    const TimedRun run = timedRun(*backend, scene, frames);
    return {run.quantileUs(0.5), run.quantileUs(0.9), run.quantileUs(0.99)};
}

TEST(BulletBaseline, WallTimePerFrame) {
    Scene drop = emptyScene(0.5, 0.5);
    addFloor(drop);
    addBall(drop, "ball", 0.1, 1.0, Vec3(0, 0, 1.1));
    const Scene pile = fallingHullCubes();
    const Percentiles a = frameTimes(drop, 600), b = frameTimes(pile, 600);
    std::printf("| scene (600 frames of 1/60 s, substeps 1) | p50 us | p90 us | p99 us |\n|---|---|---|---|\n");
    std::printf("| ball drop (1 ball + floor) | %.1f | %.1f | %.1f |\n", a.p50, a.p90, a.p99);
    std::printf("| 64 hull cubes falling on the floor | %.1f | %.1f | %.1f |\n", b.p50, b.p90, b.p99);
    EXPECT_GT(b.p50, a.p50);   // more bodies cost more
}

}  // namespace
}  // namespace vroc::test
