// SPDX-License-Identifier: MIT
// SweepAndPrune against brute-force O(n²) box overlap, frame by frame, on coherent and jumping
// motion, with static bodies, additions and removals.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <random>
#include <vector>

#include "scheduling/sweep_and_prune.h"

namespace vroc::native {
namespace {

std::vector<BodyPair> bruteForce(const std::vector<Aabb>& boxes, const std::vector<bool>& is_static,
                                 const std::vector<bool>& alive) {
    std::vector<BodyPair> out;
    for (int a = 0; a < static_cast<int>(boxes.size()); ++a) {
        for (int b = a + 1; b < static_cast<int>(boxes.size()); ++b) {
            if (!alive[a] || !alive[b] || (is_static[a] && is_static[b])) continue;
            if (boxes[a].overlaps(boxes[b])) out.push_back({a, b});
        }
    }
    return out;   // already sorted by (a, b)
}

std::string firstDifference(const std::vector<BodyPair>& got, const std::vector<BodyPair>& want) {
    std::vector<BodyPair> extra, missing;
    std::set_difference(got.begin(), got.end(), want.begin(), want.end(), std::back_inserter(extra));
    std::set_difference(want.begin(), want.end(), got.begin(), got.end(), std::back_inserter(missing));
    std::string s;
    if (!extra.empty()) s += "extra pair (" + std::to_string(extra[0].a) + "," + std::to_string(extra[0].b) + ") ";
    if (!missing.empty()) s += "missing pair (" + std::to_string(missing[0].a) + "," + std::to_string(missing[0].b) + ")";
    return s;
}

struct World {
    std::vector<Vec3> centre, velocity, half;
    std::vector<bool> is_static, alive;
    std::vector<Aabb> boxes() const {
        std::vector<Aabb> out;
        for (std::size_t i = 0; i < centre.size(); ++i) out.push_back({centre[i] - half[i], centre[i] + half[i]});
        return out;
    }
};

World randomWorld(std::mt19937_64& rng, int n, double size, double static_fraction, double grid = 0.0) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    World w;
    for (int i = 0; i < n; ++i) {
        Vec3 c(u(rng), u(rng), u(rng));
        c *= size;
        if (grid > 0) c = (c / grid).array().round().matrix() * grid;   // exact ties between boxes
        w.centre.push_back(c);
        w.velocity.push_back(Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5) * 0.02 * size);
        w.half.push_back(grid > 0 ? Vec3(Vec3::Constant(grid / 2)) : Vec3(Vec3(u(rng), u(rng), u(rng)) * 0.05 * size + Vec3::Constant(0.001)));
        w.is_static.push_back(u(rng) < static_fraction);
        w.alive.push_back(true);
    }
    return w;
}

void step(World& w, std::mt19937_64& rng, double size, double jump_probability) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (std::size_t i = 0; i < w.centre.size(); ++i) {
        if (w.is_static[i]) continue;
        if (u(rng) < jump_probability) w.centre[i] = Vec3(u(rng), u(rng), u(rng)) * size;
        w.centre[i] += w.velocity[i];
        for (int k = 0; k < 3; ++k) {   // bounce off the walls of the box [0, size]^3
            if (w.centre[i][k] < 0 || w.centre[i][k] > size) w.velocity[i][k] = -w.velocity[i][k];
        }
    }
}

// added() and removed() against the brute-force sets before and after an update.
void expectChanges(const SweepAndPrune& sap, const std::vector<BodyPair>& before, const std::vector<BodyPair>& after,
                   int frame) {
    std::vector<BodyPair> added, removed;
    std::set_difference(after.begin(), after.end(), before.begin(), before.end(), std::back_inserter(added));
    std::set_difference(before.begin(), before.end(), after.begin(), after.end(), std::back_inserter(removed));
    ASSERT_EQ(sap.added(), added) << "frame " << frame << ": " << firstDifference(sap.added(), added);
    ASSERT_EQ(sap.removed(), removed) << "frame " << frame << ": " << firstDifference(sap.removed(), removed);
}

TEST(SchedulingSweepAndPrune, MatchesBruteForceOverManyFrames) {
    for (double jump : {0.0, 0.02, 1.0}) {   // coherent, occasionally incoherent, fully random
        std::mt19937_64 rng(9);
        const double size = 10.0;
        World w = randomWorld(rng, 300, size, 0.3);
        SweepAndPrune sap;
        for (std::size_t i = 0; i < w.centre.size(); ++i) sap.addBody(w.boxes()[i], w.is_static[i]);
        std::vector<BodyPair> before;
        for (int frame = 0; frame < 100; ++frame) {
            const auto boxes = w.boxes();
            for (std::size_t i = 0; i < boxes.size(); ++i) sap.setAabb(static_cast<int>(i), boxes[i]);
            sap.update();
            const auto want = bruteForce(boxes, w.is_static, w.alive);
            ASSERT_EQ(sap.pairs(), want) << "jump=" << jump << " frame " << frame << ": "
                                         << firstDifference(sap.pairs(), want);
            expectChanges(sap, before, want, frame);
            before = want;
            for (const BodyPair& p : sap.pairs()) ASSERT_FALSE(w.is_static[p.a] && w.is_static[p.b]);
            step(w, rng, size, jump);
        }
        EXPECT_GT(sap.stats().pairs_added, 0);
    }
}

TEST(SchedulingSweepAndPrune, TouchingBoxesAndExactTiesOnAGrid) {
    std::mt19937_64 rng(10);
    World w = randomWorld(rng, 200, 4.0, 0.2, 0.5);   // unit-size grid: faces touch exactly
    SweepAndPrune sap;
    for (std::size_t i = 0; i < w.centre.size(); ++i) sap.addBody(w.boxes()[i], w.is_static[i]);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int frame = 0; frame < 60; ++frame) {
        const auto boxes = w.boxes();
        for (std::size_t i = 0; i < boxes.size(); ++i) sap.setAabb(static_cast<int>(i), boxes[i]);
        sap.update();
        const auto want = bruteForce(boxes, w.is_static, w.alive);
        ASSERT_EQ(sap.pairs(), want) << "frame " << frame << ": " << firstDifference(sap.pairs(), want);
        for (std::size_t i = 0; i < w.centre.size(); ++i) {   // moves by whole grid cells
            if (!w.is_static[i] && u(rng) < 0.3) w.centre[i][static_cast<int>(u(rng) * 3)] += (u(rng) < 0.5 ? -0.5 : 0.5);
        }
    }
}

TEST(SchedulingSweepAndPrune, AddAndRemoveBodiesWhileRunning) {
    std::mt19937_64 rng(12);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double size = 6.0;
    World w = randomWorld(rng, 50, size, 0.25);
    SweepAndPrune sap;
    for (std::size_t i = 0; i < w.centre.size(); ++i) sap.addBody(w.boxes()[i], w.is_static[i]);
    std::vector<BodyPair> before;
    for (int frame = 0; frame < 200; ++frame) {
        if (frame % 7 == 3) {   // one new body (incremental path)
            World extra = randomWorld(rng, 1, size, 0.25);
            w.centre.push_back(extra.centre[0]); w.velocity.push_back(extra.velocity[0]);
            w.half.push_back(extra.half[0]); w.is_static.push_back(extra.is_static[0]); w.alive.push_back(true);
            ASSERT_EQ(sap.addBody(w.boxes().back(), w.is_static.back()), static_cast<int>(w.centre.size()) - 1);
        }
        if (frame == 100) {   // a crowd at once (rebuild path)
            World extra = randomWorld(rng, 150, size, 0.25);
            for (int i = 0; i < 150; ++i) {
                w.centre.push_back(extra.centre[i]); w.velocity.push_back(extra.velocity[i]);
                w.half.push_back(extra.half[i]); w.is_static.push_back(extra.is_static[i]); w.alive.push_back(true);
                sap.addBody(w.boxes().back(), w.is_static.back());
            }
        }
        if (frame % 11 == 5) {
            const int victim = static_cast<int>(u(rng) * w.centre.size());
            if (w.alive[victim]) { sap.removeBody(victim); w.alive[victim] = false; }
        }
        const auto boxes = w.boxes();
        for (std::size_t i = 0; i < boxes.size(); ++i) if (w.alive[i]) sap.setAabb(static_cast<int>(i), boxes[i]);
        sap.update();
        const auto want = bruteForce(boxes, w.is_static, w.alive);
        ASSERT_EQ(sap.pairs(), want) << "frame " << frame << ": " << firstDifference(sap.pairs(), want);
        expectChanges(sap, before, want, frame);   // removeBody's pairs, the rebuild's and the sort's
        before = want;
        step(w, rng, size, 0.01);
    }
}

// An update after few boxes changed (an impact pass's kicked bodies) moves only their end points:
// the same set as brute force, and added() and removed() its changes, whether the few move a little
// or jump across the world, on free boxes and on a grid of exact ties, with bodies added and
// removed between (the full sort then), and with the few sharing an update with a box set back to
// what it was.
TEST(SchedulingSweepAndPrune, FewMovedBodiesMatchBruteForce) {
    for (double grid : {0.0, 0.5}) {
        for (int few : {1, 3, 12}) {
            std::mt19937_64 rng(static_cast<std::uint64_t>(40 + few));
            std::uniform_real_distribution<double> u(0.0, 1.0);
            const double size = grid > 0 ? 4.0 : 10.0;
            World w = randomWorld(rng, 200, size, 0.2, grid);
            SweepAndPrune sap;
            for (std::size_t i = 0; i < w.centre.size(); ++i) sap.addBody(w.boxes()[i], w.is_static[i]);
            sap.update();
            std::vector<BodyPair> before = bruteForce(w.boxes(), w.is_static, w.alive);
            for (int update = 0; update < 300; ++update) {
                if (update % 50 == 25) {   // the full path between: a body added, one removed
                    World extra = randomWorld(rng, 1, size, 0.0, grid);
                    w.centre.push_back(extra.centre[0]); w.velocity.push_back(extra.velocity[0]);
                    w.half.push_back(extra.half[0]); w.is_static.push_back(false); w.alive.push_back(true);
                    sap.addBody(w.boxes().back(), false);
                    const int victim = static_cast<int>(u(rng) * static_cast<double>(w.centre.size()));
                    if (w.alive[static_cast<std::size_t>(victim)]) {
                        sap.removeBody(victim);
                        w.alive[static_cast<std::size_t>(victim)] = false;
                    }
                }
                for (int k = 0; k < few; ++k) {
                    const auto i = static_cast<std::size_t>(u(rng) * static_cast<double>(w.centre.size()));
                    if (w.is_static[i] || !w.alive[i]) continue;
                    if (u(rng) < 0.1) {
                        w.centre[i] = Vec3(u(rng), u(rng), u(rng)) * size;
                    } else if (grid > 0) {
                        w.centre[i][static_cast<int>(u(rng) * 3)] += (u(rng) < 0.5 ? -grid : grid);
                    } else {
                        w.centre[i] += w.velocity[i] * 5.0;
                    }
                    if (grid > 0) w.centre[i] = (w.centre[i] / grid).array().round().matrix() * grid;
                    sap.setAabb(static_cast<int>(i), w.boxes()[i]);
                }
                if (update % 7 == 0) {   // a box moved and set back: no change for it
                    const int i = static_cast<int>(u(rng) * static_cast<double>(w.centre.size()));
                    if (w.alive[static_cast<std::size_t>(i)]) {
                        Aabb away = w.boxes()[static_cast<std::size_t>(i)];
                        away.lower += Vec3::Constant(1.0);
                        away.upper += Vec3::Constant(1.0);
                        sap.setAabb(i, away);
                        sap.setAabb(i, w.boxes()[static_cast<std::size_t>(i)]);
                    }
                }
                sap.update();
                const auto want = bruteForce(w.boxes(), w.is_static, w.alive);
                ASSERT_EQ(sap.pairs(), want) << "grid " << grid << ", few " << few << ", update " << update << ": "
                                             << firstDifference(sap.pairs(), want);
                expectChanges(sap, before, want, update);
                before = want;
            }
        }
    }
}

TEST(SchedulingSweepAndPrune, InvalidBoxesAreWidenedNotFatal) {
    SweepAndPrune sap;
    const int a = sap.addBody({Vec3(0, 0, 0), Vec3(1, 1, 1)}, false);
    const int b = sap.addBody({Vec3(5, 5, 5), Vec3(6, 6, 6)}, false);
    const int c = sap.addBody({Vec3(9, 9, 9), Vec3(10, 10, 10)}, true);
    sap.update();
    EXPECT_TRUE(sap.pairs().empty());
    sap.setAabb(a, {Vec3(std::nan(""), 0, 0), Vec3(1, 1, std::nan(""))});   // x below and z above unbounded
    sap.setAabb(b, {Vec3(6, 6, 6), Vec3(5, 5, 5)});                         // inverted: swapped back
    sap.update();
    EXPECT_EQ(sap.stats().invalid_boxes, 2);
    // a now spans x in (-inf, 1], y in [0, 1], z in [0, inf): overlaps neither b (y) nor c (y).
    EXPECT_TRUE(sap.pairs().empty());
    sap.setAabb(a, {Vec3::Constant(-std::numeric_limits<double>::infinity()), Vec3::Constant(std::numeric_limits<double>::infinity())});
    sap.update();
    EXPECT_EQ(sap.pairs(), (std::vector<BodyPair>{{a, b}, {a, c}}));
}

// I-COLLIDE's setting: 1,000 moving boxes, coherent motion. Prints the update time; the assertion
// is on the work done (swaps), which does not depend on the machine.
TEST(SchedulingSweepAndPrune, ThousandCoherentBodiesCheapPerFrame) {
    std::mt19937_64 rng(13);
    const double size = 20.0;
    World w = randomWorld(rng, 1000, size, 0.0);
    for (auto& v : w.velocity) v *= 0.1;   // about 1 cm per frame in a 20 m box
    SweepAndPrune sap;
    for (std::size_t i = 0; i < w.centre.size(); ++i) sap.addBody(w.boxes()[i], false);
    sap.update();
    const auto swaps_before = sap.stats().swaps;
    std::vector<double> micros;
    const int frames = 200;
    for (int frame = 0; frame < frames; ++frame) {
        step(w, rng, size, 0.0);
        const auto boxes = w.boxes();
        const auto t0 = std::chrono::steady_clock::now();
        for (std::size_t i = 0; i < boxes.size(); ++i) sap.setAabb(static_cast<int>(i), boxes[i]);
        sap.update();
        micros.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count());
        if (frame % 50 == 0) {
            const auto want = bruteForce(boxes, w.is_static, w.alive);
            ASSERT_EQ(sap.pairs(), want) << firstDifference(sap.pairs(), want);
        }
    }
    std::sort(micros.begin(), micros.end());
    const double swaps_per_frame = static_cast<double>(sap.stats().swaps - swaps_before) / frames;
    std::printf("[info] 1000 coherent bodies: median %.1f us, max %.1f us per update, %.0f swaps per frame, %zu pairs\n",
                micros[frames / 2], micros.back(), swaps_per_frame, sap.pairs().size());
    // O(n + changes): a few swaps per end point and axis, far from the ~n² of sorting from scratch.
    EXPECT_LT(swaps_per_frame, 10.0 * 1000);
}

}  // namespace
}  // namespace vroc::native
