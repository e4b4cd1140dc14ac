// SPDX-License-Identifier: MIT
// Determinism: the same scene run twice, and with 1, 2 and 4 workers, gives one state hash.
#include <gtest/gtest.h>

#include <random>

#include "native_test_scenes.h"
#include "vroc/core/state_hash.h"

namespace vroc::native::test {
namespace {

Scene pileScene() {
    Scene s = bareScene(1e-3);
    const int mat = addMaterial(s, 0.4, 0.5);
    addFloor(s, mat, 20.0);
    std::mt19937_64 rng(99);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 24; ++i) {
        const Vec3 p(0.6 * u(rng), 0.6 * u(rng), 0.4 + 0.35 * i);
        const Quat q(Eigen::AngleAxisd(3 * u(rng), Vec3(u(rng), u(rng), u(rng)).normalized()));
        if (i % 2 == 0) {
            addBody(s, "ball" + std::to_string(i), Shape::sphere(0.1 + 0.05 * std::abs(u(rng))), at(p, q), mat, false);
        } else {
            addBody(s, "box" + std::to_string(i), Shape::box(Vec3(0.12, 0.08, 0.1)), at(p, q), mat, false);
        }
        s.bodies.back().linear_velocity = Vec3(u(rng), u(rng), 0);
        s.bodies.back().angular_velocity = 3 * Vec3(u(rng), u(rng), u(rng));
    }
    return s;
}

// A 2-D pyramid of boxes, base `base`, 0.5 mm apart: one island of base^2-ish manifolds.
Scene pyramidScene(int base) {
    Scene s = bareScene(1e-3);
    const int mat = addMaterial(s, 0.0, 0.6);
    addFloor(s, mat, 20.0);
    const double half = 0.1, gap = 5e-4;
    for (int row = 0; row < base; ++row)
        for (int k = 0; k < base - row; ++k) {
            const double x = (k - 0.5 * (base - row - 1)) * (2 * half + gap);
            addBody(s, "box" + std::to_string(row) + "_" + std::to_string(k), Shape::box(Vec3(half, half, half)),
                    at(Vec3(x, 0, half + gap + row * (2 * half + gap))), mat, false);
        }
    return s;
}

std::uint64_t runHash(const Scene& s, int threads, int frames, double* largest_island = nullptr) {
    NativeSettings ns;
    ns.threads = threads;
    auto be = makeBackend(s, ns);
    for (int f = 0; f < frames; ++f) be->stepFrame(s.frame_dt);
    if (largest_island != nullptr) *largest_island = be->statistics().at("native.max_island_bodies");
    return stateHash(*be);
}

std::uint64_t runHash(int threads, int frames) {
    const Scene s = pileScene();
    NativeSettings ns;
    ns.threads = threads;
    auto be = makeBackend(s, ns);
    for (int f = 0; f < frames; ++f) be->stepFrame(s.frame_dt);
    return stateHash(*be);
}

TEST(NativeDeterminism, SameSceneTwiceAndAnyThreadCountGiveOneHash) {
    const int frames = 90;
    const std::uint64_t h1 = runHash(1, frames);
    EXPECT_EQ(runHash(1, frames), h1);
    EXPECT_EQ(runHash(2, frames), h1);
    EXPECT_EQ(runHash(4, frames), h1);
}

// One large island: its sweeps are shared by the workers in colour groups, and the result must not
// depend on how many there are.
TEST(NativeDeterminism, OneLargeIslandGivesOneHashForAnyThreadCount) {
    const Scene s = pyramidScene(12);
    double largest = 0.0;
    const std::uint64_t h1 = runHash(s, 1, 20, &largest);
    EXPECT_GE(largest, 78.0) << "the pyramid should be one island";
    EXPECT_EQ(runHash(s, 2, 20), h1);
    EXPECT_EQ(runHash(s, 3, 20), h1);
}

// A heavy box thrown into the pyramid: its blow runs through one large island, whose collision
// phase the workers share wave by wave (impulse_waves.h), on both regimes; any worker count gives
// the one-worker hash.
TEST(NativeDeterminism, BlowIntoALargeIslandGivesOneHashForAnyThreadCount) {
    Scene s = pyramidScene(12);
    const int mat = s.bodies.back().material;
    addBody(s, "striker", Shape::box(Vec3(0.15, 0.15, 0.15)), at(Vec3(-2.0, 0, 0.4)), mat, false, 10.0);
    s.bodies.back().linear_velocity = Vec3(12.0, 0, 0);
    for (TouchingRegime regime : {TouchingRegime::Protected, TouchingRegime::Fixed}) {
        std::vector<std::uint64_t> hashes;
        for (int threads : {1, 2, 3}) {
            NativeSettings ns;
            ns.threads = threads;
            ns.touching = regime;
            auto be = makeBackend(s, ns);
            for (int f = 0; f < 40; ++f) be->stepFrame(s.frame_dt);
            EXPECT_GE(be->statistics().at("native.max_island_bodies"), 78.0) << "the pyramid should be one island";
            EXPECT_GT(be->statistics().at("collision_events"), 0.0) << "the striker meets the pyramid";
            hashes.push_back(stateHash(*be));
        }
        EXPECT_EQ(hashes[1], hashes[0]) << "regime " << static_cast<int>(regime);
        EXPECT_EQ(hashes[2], hashes[0]) << "regime " << static_cast<int>(regime);
    }
}

TEST(NativeDeterminism, PileSettlesWithoutNumericalTrouble) {
    const Scene s = pileScene();
    auto be = makeBackend(s);
    for (int f = 0; f < 180; ++f) be->stepFrame(s.frame_dt);
    for (int i = 1; i < be->bodyCount(); ++i) {   // body 0 is the floor
        const BodyState st = be->bodyState(i);
        ASSERT_TRUE(st.pose.position.allFinite() && st.linear_velocity.allFinite());
        EXPECT_GT(st.pose.position.z(), -1e-3) << s.bodies[i].name << " fell through the floor";
    }
    EXPECT_EQ(be->warnings().count("nonfinite_state"), 0u);
}

}  // namespace
}  // namespace vroc::native::test
