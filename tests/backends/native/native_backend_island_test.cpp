// SPDX-License-Identifier: MIT
// Islands (docs/native-scheduling.md §9): an event in one island never touches another, a pile
// costs one solve per tick, bodies changed by an impulse have their other pairs bounded again at
// once, and the mass-ratio stack holds. Independent answers: the same island simulated alone,
// closed-form flight, a brute-force union-find.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "native_test_scenes.h"
#include "scheduling/island_builder.h"

namespace vroc::native::test {
namespace {

// A stack of `n` boxes (0.5 m) centred at (x, 0), placed half the collision distance apart.
void addStack(Scene& s, int mat, double x, int n, double cd, double mass_odd = 1.0) {
    for (int i = 0; i < n; ++i) {
        const double z = 0.25 + 0.5 * cd + i * (0.5 + 0.5 * cd);
        addBody(s, "box" + std::to_string(s.bodies.size()), Shape::box(Vec3(0.25, 0.25, 0.25)), at(Vec3(x, 0, z)),
                mat, false, i % 2 == 0 ? 1.0 : mass_odd);
    }
}

// A floor and the piles' material (e = 0, mu = 0.6).
Scene restingScene(double cd, int& mat) {
    Scene s = bareScene(cd);
    mat = addMaterial(s, 0.0, 0.6);
    addFloor(s, mat, 20.0);
    return s;
}

bool sameBits(const BodyState& a, const BodyState& b) {
    return std::memcmp(a.pose.position.data(), b.pose.position.data(), sizeof(double) * 3) == 0 &&
           std::memcmp(a.pose.orientation.coeffs().data(), b.pose.orientation.coeffs().data(), sizeof(double) * 4) == 0 &&
           std::memcmp(a.linear_velocity.data(), b.linear_velocity.data(), sizeof(double) * 3) == 0;
}

TEST(NativeIslands, AnImpactElsewhereLeavesAnIslandBitIdentical) {
    // Stack A alone, and stack A beside a far stack B that a ball hits repeatedly: A must evolve
    // with the same bits (its ticks are its own; B's impacts neither shorten nor read them).
    const double cd = 1e-3;
    auto build = [&](bool with_b) {
        Scene s = bareScene(cd);
        const int mat = addMaterial(s, 0.3, 0.5);
        addFloor(s, mat, 20.0);
        addStack(s, mat, 0.0, 5, cd);
        if (with_b) {
            addStack(s, mat, 5.0, 5, cd);
            addBody(s, "ball", Shape::sphere(0.1), at(Vec3(5.0, 0, 4.0)), mat, false, 2.0);
        }
        return s;
    };
    const Scene alone = build(false), both = build(true);
    auto a = makeBackend(alone);
    auto b = makeBackend(both);
    std::size_t impacts_b = 0;
    for (int f = 0; f < 120; ++f) {
        a->stepFrame(alone.frame_dt);
        b->stepFrame(both.frame_dt);
        for (const CollisionEvent& e : b->takeEvents())
            if (e.body_a > 5 || e.body_b > 5) ++impacts_b;
        for (int body = 1; body <= 5; ++body)
            ASSERT_TRUE(sameBits(a->bodyState(body), b->bodyState(body))) << "frame " << f << " body " << body;
    }
    EXPECT_GT(impacts_b, 0u) << "the ball must hit stack B for the test to mean anything";
    EXPECT_GT(b->statistics().at("internal_steps"), a->statistics().at("internal_steps"));
}

TEST(NativeIslands, RestingPileIsSolvedOncePerTick) {
    const double cd = 1e-3;
    int mat = -1;
    Scene s = restingScene(cd, mat);
    addStack(s, mat, 0.0, 6, cd);
    addStack(s, mat, 2.0, 6, cd);
    for (int substeps : {1, 4}) {
        NativeSettings ns;
        ns.contact_substeps = substeps;
        auto be = makeBackend(s, ns);
        for (int f = 0; f < 60; ++f) be->stepFrame(s.frame_dt);
        const auto st = be->statistics();
        // Two islands, each solved at each of its ticks: 2 x substeps solves per frame.
        EXPECT_EQ(st.at("native.contact_solves"), 2.0 * substeps * 60) << "substeps " << substeps;
        EXPECT_EQ(st.at("internal_steps"), substeps * 60.0) << "substeps " << substeps;
        // Why they ran: each island's first solve when its contacts are found, every other one on
        // the grid, no protection tick; each island is a stack of 6 and its floor.
        EXPECT_EQ(st.at("native.solves_new_contact"), 2.0) << "substeps " << substeps;
        EXPECT_EQ(st.at("native.solves_on_grid"), st.at("native.contact_solves") - 2.0) << "substeps " << substeps;
        EXPECT_EQ(st.at("native.solves_protection"), 0.0) << "substeps " << substeps;
        EXPECT_EQ(st.at("native.solved_bodies_per_solve"), 7.0) << "substeps " << substeps;
        for (int body = 1; body < static_cast<int>(s.bodies.size()); ++body)
            EXPECT_LT(be->bodyState(body).linear_velocity.norm(), 1e-6);
    }
}

// The solve counts say why each solve ran, and add up: a spinning box dropped on its corner has a
// new contact (its landing), protection ticks (its tumbling vertices may close before the next
// grid tick: the per-point bound) and grid ticks once it lies still.
TEST(NativeIslands, SolveCountsSayWhyEachSolveRan) {
    const double cd = 1e-3;
    int mat = -1;
    Scene s = restingScene(cd, mat);
    const Quat tilt(Eigen::AngleAxisd(0.6, Vec3(1, 1, 0).normalized()));
    addBody(s, "box", Shape::box(Vec3(0.25, 0.25, 0.25)), at(Vec3(0, 0, 1.0), tilt), mat, false, 1.0);
    s.bodies.back().angular_velocity = Vec3(3, -2, 5);
    auto be = makeBackend(s);
    for (int f = 0; f < 180; ++f) be->stepFrame(s.frame_dt);
    const auto st = be->statistics();
    EXPECT_EQ(st.at("native.solves_on_grid") + st.at("native.solves_protection") + st.at("native.solves_new_contact"),
              st.at("native.contact_solves"));
    EXPECT_GE(st.at("native.solves_new_contact"), 1.0);
    EXPECT_GT(st.at("native.solves_protection"), 0.0);
    EXPECT_GT(st.at("native.solves_on_grid"), 60.0);  // at rest for the last second at least
    EXPECT_EQ(st.at("native.solved_bodies_per_solve"), 2.0);
    EXPECT_LT(be->bodyState(1).linear_velocity.norm(), 1e-6);
}

TEST(NativeIslands, MassRatioStackHolds) {
    // 20 boxes alternating 1 kg and 10 kg (the 1:10 stack): 10 s, top drift <= 1 cm.
    const double cd = 1e-3;
    int mat = -1;
    Scene s = restingScene(cd, mat);
    addStack(s, mat, 0.0, 20, cd, 10.0);
    const int top = static_cast<int>(s.bodies.size()) - 1;
    auto be = makeBackend(s);
    const Vec3 start = be->bodyState(top).pose.position;
    for (int f = 0; f < 600; ++f) be->stepFrame(s.frame_dt);
    EXPECT_LE((be->bodyState(top).pose.position - start).norm(), 0.01);
    EXPECT_EQ(be->warnings().count("penetration_recovered"), 0u);
}

TEST(NativeIslands, BounceOffTheFloorIntoASlabAboveIsMet) {
    // A ball resting on the floor is kicked upwards (applyImpulse) into a real slab 2 cm above its
    // top: its pair with the slab must be bounded with the new velocity at once, so the ball is
    // stopped by the slab and never passes into it (neutral check: its top stays below the slab).
    const double cd = 1e-3, r = 0.1;
    Scene s = bareScene(cd);
    const int mat = addMaterial(s, 0.5, 0.0);
    addFloor(s, mat, 20.0);
    const double slab_bottom = 2 * r + 0.5 * cd + 0.02;
    addBody(s, "slab", Shape::box(Vec3(1, 1, 0.01)), at(Vec3(0, 0, slab_bottom + 0.01)), mat, true);
    const int ball = addBody(s, "ball", Shape::sphere(r), at(Vec3(0, 0, r + 0.5 * cd)), mat, false, 1.0);
    auto be = makeBackend(s);
    for (int f = 0; f < 10; ++f) be->stepFrame(s.frame_dt);
    be->applyImpulse(ball, Vec3(0, 0, 5.0), be->bodyState(ball).pose.position);   // 5 m/s up
    bool hit_slab = false;
    for (int f = 0; f < 30; ++f) {
        be->stepFrame(s.frame_dt);
        for (const CollisionEvent& e : be->takeEvents())
            if (e.body_a == 1 || e.body_b == 1) hit_slab = true;
        EXPECT_LE(be->bodyState(ball).pose.position.z() + r, slab_bottom + 1e-9) << "frame " << f;
    }
    EXPECT_TRUE(hit_slab);
}

TEST(NativeIslands, IslandBuilderMatchesBruteForceComponents) {
    std::mt19937 rng(7);
    for (int trial = 0; trial < 50; ++trial) {
        const int n = 40;
        std::vector<bool> is_static(n);
        for (int i = 0; i < n; ++i) is_static[static_cast<std::size_t>(i)] = (rng() % 7) == 0;
        std::vector<std::pair<int, int>> edges;
        for (int k = 0; k < 30; ++k) edges.emplace_back(static_cast<int>(rng() % n), static_cast<int>(rng() % n));
        IslandBuilder ib;
        ib.reset(is_static);
        for (auto [a, b] : edges) ib.join(a, b);
        // Brute force: repeated relaxation of the smallest label over edges between dynamic bodies.
        std::vector<int> label(n);
        for (int i = 0; i < n; ++i) label[static_cast<std::size_t>(i)] = is_static[static_cast<std::size_t>(i)] ? -1 : i;
        for (bool changed = true; changed;) {
            changed = false;
            for (auto [a, b] : edges) {
                if (is_static[static_cast<std::size_t>(a)] || is_static[static_cast<std::size_t>(b)]) continue;
                const int m = std::min(label[static_cast<std::size_t>(a)], label[static_cast<std::size_t>(b)]);
                for (int v : {a, b})
                    if (label[static_cast<std::size_t>(v)] != m) {
                        label[static_cast<std::size_t>(v)] = m;
                        changed = true;
                    }
            }
        }
        for (int i = 0; i < n; ++i) EXPECT_EQ(ib.islandOf(i), label[static_cast<std::size_t>(i)]) << "body " << i;
    }
}

TEST(NativeIslands, SleepingIsOffByDefaultAndAPileSleepsAndWakes) {
    const double cd = 1e-3;
    int mat = -1;
    Scene s = restingScene(cd, mat);
    addStack(s, mat, 0.0, 4, cd);
    const int ball = addBody(s, "ball", Shape::sphere(0.1), at(Vec3(0, 0, 6.0)), mat, false, 1.0);
    // Off by default: the pile is solved at every tick.
    auto awake = makeBackend(s);
    for (int f = 0; f < 60; ++f) awake->stepFrame(s.frame_dt);
    EXPECT_EQ(awake->statistics().at("native.islands_slept"), 0.0);
    // On: the pile sleeps after 0.5 s still, costs nothing, and wakes when the ball lands on it.
    NativeSettings ns;
    ns.sleeping = true;
    auto be = makeBackend(s, ns);
    const Vec3 top_start = be->bodyState(4).pose.position;
    double solves_asleep = -1.0;
    bool woke = false;
    for (int f = 0; f < 90; ++f) {
        be->stepFrame(s.frame_dt);
        const double solves = be->statistics().at("native.contact_solves");
        if (f == 45) solves_asleep = solves;
        if (f > 45 && f < 50) {
            EXPECT_EQ(solves, solves_asleep) << "frame " << f;   // asleep, ball still falling
        }
        if (!be->takeEvents().empty() && f > 45) woke = true;
    }
    EXPECT_GE(be->statistics().at("native.islands_slept"), 1.0);
    EXPECT_TRUE(woke) << "the ball (falling from 6 m, lands at ~1.0 s) must hit the pile";
    EXPECT_GT(be->statistics().at("native.contact_solves"), solves_asleep);
    EXPECT_LT((be->bodyState(4).pose.position - top_start).norm(), 0.02);   // the pile still stands
    (void)ball;
}

}  // namespace
}  // namespace vroc::native::test
