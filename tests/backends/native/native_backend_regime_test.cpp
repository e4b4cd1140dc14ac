// SPDX-License-Identifier: MIT
// The two regimes (docs/native-dynamics.md, "Two regimes"): boxes dropped tumbling onto the floor
// land on corners and edges and tip over faces. In the speculative regime the faces beyond an edge
// enter the solve as speculative points, with no protection tick: every frame, no corner of any box
// may be deeper below the floor than the collision distance (the boxes' corners from their poses:
// an independent ruler), nothing is repaired by moving bodies, and the boxes come to rest. The soft
// regime (Box2D v3's sub-stepped solve in each tick) is held to the same.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "native_test_scenes.h"
#include "vroc/core/state_hash.h"

namespace vroc::native::test {
namespace {

struct Dropped {
    Scene scene;
    std::vector<int> boxes;
    std::vector<Vec3> half;
};

Dropped tumblingBoxes(double cd, std::uint64_t seed) {
    Dropped d;
    d.scene = bareScene(cd);
    const int mat = addMaterial(d.scene, 0.1, 0.5);
    addFloor(d.scene, mat, 20.0);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 6; ++i) {
        const Vec3 h(0.05 + 0.05 * std::abs(u(rng)), 0.05 + 0.05 * std::abs(u(rng)), 0.02 + 0.08 * std::abs(u(rng)));
        const Quat q(Eigen::AngleAxisd(3.0 * u(rng), Vec3(u(rng), u(rng), u(rng)).normalized()));
        d.boxes.push_back(addBody(d.scene, "box" + std::to_string(i), Shape::box(h),
                                  at(Vec3(0.6 * (i % 3) - 0.6, 0.6 * (i / 3) - 0.3, 0.4 + 0.2 * std::abs(u(rng))), q), mat,
                                  false, 1.0));
        d.half.push_back(h);
    }
    return d;
}

const char* regimeName(TouchingRegime r) {
    return r == TouchingRegime::Speculative ? "speculative"
           : r == TouchingRegime::Soft      ? "soft"
           : r == TouchingRegime::Fixed     ? "fixed"
           : r == TouchingRegime::FixedSoft ? "fixed-soft"
                                            : "protected";
}

TEST(NativeRegimes, TumblingBoxesLandWithinTheCollisionDistanceAndRest) {
    const double cd = 1e-3;
    for (std::uint64_t seed : {1u, 2u, 3u}) {
        for (TouchingRegime regime : {TouchingRegime::Speculative, TouchingRegime::Protected, TouchingRegime::Soft}) {
            const Dropped d = tumblingBoxes(cd, seed);
            NativeSettings ns;
            ns.touching = regime;
            auto be = makeBackend(d.scene, ns);
            const char* name = regimeName(regime);
            double deepest = 0.0;
            for (int f = 0; f < 180; ++f) {
                be->stepFrame(d.scene.frame_dt);
                for (std::size_t k = 0; k < d.boxes.size(); ++k)
                    deepest = std::max(deepest, depthBelowFloor(be->bodyState(d.boxes[k]), d.half[k]));
            }
            EXPECT_LE(deepest, cd) << name << ", seed " << seed;
            EXPECT_EQ(be->warnings().count("penetration_recovered"), 0u) << name << ", seed " << seed;
            for (int b : d.boxes)
                EXPECT_LT(be->bodyState(b).linear_velocity.norm(), 1e-3) << name << ", seed " << seed << ", body " << b;
        }
    }
}

TEST(NativeRegimes, HeldBodiesNeedNoStepsBetweenTheirTicks) {
    // Once the boxes rest, the speculative regime takes one internal step per sub-step, the
    // protected one at least as many.
    const Dropped d = tumblingBoxes(1e-3, 4);
    double steps[2] = {0.0, 0.0};
    int k = 0;
    for (TouchingRegime regime : {TouchingRegime::Speculative, TouchingRegime::Protected}) {
        NativeSettings ns;
        ns.touching = regime;
        auto be = makeBackend(d.scene, ns);
        for (int f = 0; f < 180; ++f) be->stepFrame(d.scene.frame_dt);
        const double before = be->statistics().at("internal_steps");
        for (int f = 0; f < 60; ++f) be->stepFrame(d.scene.frame_dt);
        steps[k++] = be->statistics().at("internal_steps") - before;
    }
    EXPECT_EQ(steps[0], 60.0) << "speculative: one step per frame at rest";
    EXPECT_GE(steps[1], steps[0]);
}

// Steps `frames` frames; the deepest overlap of neighbours in the row meanwhile (rowOverlap).
double deepestRowOverlap(Backend& be, const Scene& s, const std::vector<int>& row, double half, int frames) {
    double overlap = 0.0;
    for (int f = 0; f < frames; ++f) {
        be.stepFrame(s.frame_dt);
        overlap = std::max(overlap, rowOverlap(be, row, half));
    }
    return overlap;
}

// A box at 7 m/s runs into a row of resting boxes 1 cm apart, on a frictionless floor. Each impact
// sets a box moving that the solve did not hold against its neighbour (not yet touching then): its
// pair must still be met before it closes (it was in no solve), in every regime. Momentum goes down
// the row: the last box leaves with the most of it, every box keeps within the collision distance of
// its neighbours (their x positions: an independent ruler), and no penetration is repaired.
TEST(NativeRegimes, ImpactRunsDownARowWithoutPenetration) {
    const double cd = 1e-3, half = 0.25, pitch = 2 * half + 0.01;
    for (TouchingRegime regime : {TouchingRegime::Speculative, TouchingRegime::Protected, TouchingRegime::Soft,
                                  TouchingRegime::Fixed, TouchingRegime::FixedSoft}) {
        Scene s = bareScene(cd);
        const int mat = addMaterial(s, 0.0, 0.0);
        addFloor(s, mat, 20.0);
        std::vector<int> row;
        for (int i = 0; i < 4; ++i)
            row.push_back(addBody(s, "box" + std::to_string(i), Shape::box(Vec3(half, half, half)),
                                  at(Vec3(pitch * i, 0, half + 0.5 * cd)), mat, false, 1.0));
        s.bodies[static_cast<std::size_t>(row[0])].linear_velocity = Vec3(7.0, 0, 0);
        NativeSettings ns;
        ns.touching = regime;
        auto be = makeBackend(s, ns);
        const double overlap = deepestRowOverlap(*be, s, row, half, 30);
        const char* name = regimeName(regime);
        EXPECT_LE(overlap, cd) << name;
        EXPECT_EQ(be->warnings().count("penetration_recovered"), 0u) << name;
        double momentum = 0.0;
        for (int b : row) momentum += be->bodyState(b).linear_velocity.x();
        EXPECT_NEAR(momentum, 7.0, 0.05) << name << ": momentum along the row (1 kg boxes, no friction)";
        EXPECT_GT(be->bodyState(row.back()).linear_velocity.x(), 0.5 * 7.0 / row.size()) << name;
    }
}

// A 10 kg ball at 15 m/s strikes the first of ten touching 1 kg boxes (no gap between them) on a
// frictionless floor, everything plastic: the blow must cross the whole row at once. The collision
// phase passes it on about one box a sweep, so with five sweeps the row squeezed itself by 133 mm
// (a base-12 pyramid built without gaps repaired 995 penetrations, 61 mm deep, in the event-driven
// regime); with 20 it still overlapped by 15-29 mm. Closed forms: momentum 150 N s is kept (to
// 0.5 %), and the plastic end state is the row and the ball moving together at 150 / 20 = 7.5 m/s
// (to 1 %); neighbours stay within the collision distance (their x positions: an independent
// ruler) and nothing is repaired. For any worker count, the same bits.
TEST(NativeRegimes, AHeavyBallsBlowCrossesARowOfTouchingBoxes) {
    const double cd = 1e-3, half = 0.25, radius = 0.2, v0 = 15.0;
    const int boxes = 10;
    Scene s = bareScene(cd);
    const int mat = addMaterial(s, 0.0, 0.0);
    addFloor(s, mat, 20.0);
    std::vector<int> row;
    for (int i = 0; i < boxes; ++i)
        row.push_back(vroc::test::addBox(s, "box" + std::to_string(i), Vec3(half, half, half), 1.0, Vec3(2 * half * i, 0, half + 0.5 * cd), mat));
    const int ball = vroc::test::addBall(s, "ball", radius, 10.0, Vec3(-half - radius - 0.1, 0, half + 0.5 * cd), mat);
    s.bodies[static_cast<std::size_t>(ball)].linear_velocity = Vec3(v0, 0, 0);
    std::vector<std::uint64_t> hashes;
    for (int threads : {1, 2}) {
        NativeSettings ns;
        ns.threads = threads;
        auto be = makeBackend(s, ns);
        const double overlap = deepestRowOverlap(*be, s, row, half, 12);
        EXPECT_LE(overlap, cd) << threads << " workers";
        EXPECT_EQ(be->warnings().count("penetration_recovered"), 0u) << threads << " workers";
        double momentum = 10.0 * be->bodyState(ball).linear_velocity.x();
        for (int b : row) momentum += be->bodyState(b).linear_velocity.x();
        EXPECT_NEAR(momentum, 10.0 * v0, 5e-3 * 10.0 * v0) << threads << " workers";
        const double common = 10.0 * v0 / (10.0 + boxes);
        EXPECT_NEAR(be->bodyState(ball).linear_velocity.x(), common, 0.01 * common) << threads << " workers";
        for (int b : row) EXPECT_NEAR(be->bodyState(b).linear_velocity.x(), common, 0.01 * common) << "box " << b;
        hashes.push_back(stateHash(*be));
    }
    EXPECT_EQ(hashes[0], hashes[1]);
}

// The soft regime gives the same bits for any worker count (its island solves are shared out as the
// other regimes' are).
TEST(NativeRegimes, SoftRegimeIsDeterministicForAnyThreadCount) {
    const Dropped d = tumblingBoxes(1e-3, 5);
    std::vector<std::uint64_t> hashes;
    for (int threads : {1, 2, 3}) {
        NativeSettings ns;
        ns.touching = TouchingRegime::Soft;
        ns.threads = threads;
        auto be = makeBackend(d.scene, ns);
        for (int f = 0; f < 90; ++f) be->stepFrame(d.scene.frame_dt);
        hashes.push_back(stateHash(*be));
    }
    EXPECT_EQ(hashes[1], hashes[0]);
    EXPECT_EQ(hashes[2], hashes[0]);
}

}  // namespace
}  // namespace vroc::native::test
