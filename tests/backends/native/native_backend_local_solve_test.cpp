// SPDX-License-Identifier: MIT
// Local protection solves (native.protection_ring; docs/native-dynamics.md, "Local protection
// solves"): a protection tick off the grid solves only the bodies near those whose tick came and
// holds the next ring as ground. A falling row of dominoes is one growing island with protection
// ticks at every tipping domino.
//   - A ring wider than the island holds nothing: every step must then be bit-identical to solving
//     the whole island (the machinery adds no arithmetic of its own).
//   - With ring 0 the ticks hold neighbours as ground: the chain must still fall all the way, no
//     domino corner may sink below the floor by more than the collision distance (corners from the
//     poses: an independent ruler), nothing is repaired, and the bits do not depend on the workers.
#include <cmath>

#include <gtest/gtest.h>

#include "native_test_scenes.h"
#include "vroc/core/state_hash.h"

namespace vroc::native::test {
namespace {

constexpr int kDominoes = 10;
const Vec3 kHalf(0.01, 0.05, 0.1);

struct Row {
    Scene scene;
    std::vector<int> dominoes;
};

// dominoes60's row (scenes/stress/generate_stress.py), shortened: 0.1 m apart, the first tipped by
// 15 degrees against the second.
Row dominoRow() {
    Row r;
    r.scene = bareScene(1e-3);
    const int wood = addMaterial(r.scene, 0.0, 0.6);
    addFloor(r.scene, wood, 5.0);
    for (int i = 0; i < kDominoes; ++i) {
        Pose p = at(Vec3(0.1 * i, 0, kHalf.z() + 0.5e-3));
        if (i == 0)
            p = at(Vec3(0.1 - 0.073777354, 0, 0.099680773), Quat(Eigen::AngleAxisd(15.0 * M_PI / 180.0, Vec3::UnitY())));
        r.dominoes.push_back(addBody(r.scene, "domino" + std::to_string(i), Shape::box(kHalf), p, wood, false, 0.25));
    }
    return r;
}

double deepestCorner(const BodyState& st) {
    double lowest = 1e9;
    for (int c = 0; c < 8; ++c) {
        const Vec3 corner((c & 1 ? 1 : -1) * kHalf.x(), (c & 2 ? 1 : -1) * kHalf.y(), (c & 4 ? 1 : -1) * kHalf.z());
        lowest = std::min(lowest, st.pose.apply(corner).z());
    }
    return -lowest;
}

// Angle [rad] between a domino's long axis and the vertical.
double tipAngle(const BodyState& st) {
    return std::acos(std::clamp((st.pose.orientation * Vec3::UnitZ()).z(), -1.0, 1.0));
}

TEST(NativeLocalSolves, ARingWiderThanTheIslandIsTheWholeIslandSolve) {
    const Row row = dominoRow();
    NativeSettings whole;
    NativeSettings wide;
    wide.protection_ring = 1000;
    auto a = makeBackend(row.scene, whole);
    auto b = makeBackend(row.scene, wide);
    for (int f = 0; f < 90; ++f) {
        a->stepFrame(row.scene.frame_dt);
        b->stepFrame(row.scene.frame_dt);
        ASSERT_EQ(stateHash(*a), stateHash(*b)) << "frame " << f;
    }
    EXPECT_GT(b->statistics().at("native.solves_local"), 0.0) << "the row must have had protection ticks";
    EXPECT_EQ(b->statistics().at("native.local_held_bodies"), 0.0);
    EXPECT_EQ(a->statistics().at("native.solves_local"), 0.0);
}

TEST(NativeLocalSolves, RingZeroHoldsNeighboursAndTheRowStillFalls) {
    const Row row = dominoRow();
    std::vector<std::uint64_t> hashes;
    for (int threads : {1, 2}) {
        NativeSettings ns;
        ns.protection_ring = 0;
        ns.threads = threads;
        auto be = makeBackend(row.scene, ns);
        double deepest = 0.0;
        for (int f = 0; f < 150; ++f) {
            be->stepFrame(row.scene.frame_dt);
            for (int d : row.dominoes) deepest = std::max(deepest, deepestCorner(be->bodyState(d)));
        }
        hashes.push_back(stateHash(*be));
        EXPECT_LE(deepest, row.scene.collision_distance) << threads << " workers";
        EXPECT_EQ(be->warnings().count("penetration_recovered"), 0u);
        EXPECT_GT(be->statistics().at("native.local_held_bodies"), 0.0) << "ring 0 must hold neighbours as ground";
        // Every domino but the last leans on the next one (about 30 degrees at a spacing of 0.1 m
        // and a height of 0.2 m); the last lies on the floor (90 degrees).
        for (int k = 0; k + 1 < kDominoes; ++k)
            EXPECT_GT(tipAngle(be->bodyState(row.dominoes[static_cast<std::size_t>(k)])), 0.3) << "domino " << k;
        EXPECT_GT(tipAngle(be->bodyState(row.dominoes.back())), 1.2) << "the last domino";
    }
    EXPECT_EQ(hashes[1], hashes[0]) << "same bits for 1 and 2 workers";
}

}  // namespace
}  // namespace vroc::native::test
