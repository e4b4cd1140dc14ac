// SPDX-License-Identifier: MIT
// Fixed ticks (native.touching=fixed, fixed-soft; docs/native-dynamics.md, "Fixed ticks"): every pair
// sampled and every island solved at native.contact_substeps ticks per frame, with speculative points
// for what a pair may close within a tick. Checked against independent answers: the closed form of
// free flight, the corners of boxes below the floor from their poses, the tick count of the schedule,
// and the state hash for several worker counts.
#include <cmath>
#include <limits>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "native_test_scenes.h"
#include "vroc/core/state_hash.h"

namespace vroc::native::test {
namespace {

NativeSettings fixedSettings(TouchingRegime regime, int threads = 1) {
    NativeSettings ns;
    ns.touching = regime;
    ns.threads = threads;
    return ns;
}

const char* name(TouchingRegime r) { return r == TouchingRegime::Fixed ? "fixed" : "fixed-soft"; }

// The deepest penetration [m] (the backend's own neutral distance query, every sample) over `frames`
// frames of `s` with `ns`, which must repair nothing (`label` names the run); its final state hash
// into `hash` if given.
double deepestOver(const Scene& s, const NativeSettings& ns, int frames, std::uint64_t* hash, const std::string& label) {
    auto be = makeBackend(s, ns);
    for (int f = 0; f < frames; ++f) be->stepFrame(s.frame_dt);
    EXPECT_EQ(be->warnings().count("penetration_recovered"), 0u) << label;
    if (hash != nullptr) *hash = stateHash(*be);
    return be->statistics().at("native.deepest_penetration_m");
}

// A 1 kg body of `shape` alone above a real floor (top at z = 0, collision distance 1 mm), its
// lowest point `h` above it, restitution e and friction mu against it; `body` is its index.
Scene dropOntoFloor(const Shape& shape, double lowest, double h, double e, double mu, int& body) {
    Scene s = bareScene(1e-3);
    const int mat = addMaterial(s, e, mu);
    addFloor(s, mat, 5.0);
    body = addBody(s, "dropped", shape, at(Vec3(0.0, 0.0, lowest + h)), mat, false, 1.0);
    return s;
}

// A box thrown high above the floor meets nothing within reach: it flies exactly, as the closed form
// of a parabola and a constant spin about a principal axis says, at every frame end.
TEST(NativeFixedTicks, BodyOutOfReachFliesExactly) {
    for (TouchingRegime regime : {TouchingRegime::Fixed, TouchingRegime::FixedSoft}) {
        Scene s = bareScene(1e-3);
        const int mat = addMaterial(s, 0.5, 0.5);
        addFloor(s, mat, 20.0);
        const Vec3 x0(0.3, -0.2, 30.0), v0(1.5, -0.5, 4.0), w0(0.0, 0.0, 2.0);
        const int box = addBody(s, "box", Shape::box(Vec3(0.1, 0.2, 0.3)), at(x0), mat, false, 2.0);
        s.bodies[static_cast<std::size_t>(box)].linear_velocity = v0;
        s.bodies[static_cast<std::size_t>(box)].angular_velocity = w0;
        auto be = makeBackend(s, fixedSettings(regime));
        for (int f = 1; f <= 60; ++f) {
            be->stepFrame(s.frame_dt);
            const double t = f * s.frame_dt;
            const BodyState st = be->bodyState(box);
            const Vec3 x = x0 + v0 * t + 0.5 * t * t * s.gravity;
            EXPECT_LT((st.pose.position - x).norm(), 1e-12) << name(regime) << ", frame " << f;
            EXPECT_LT((st.linear_velocity - (v0 + s.gravity * t)).norm(), 1e-12) << name(regime) << ", frame " << f;
            const Quat q(Eigen::AngleAxisd(w0.z() * t, Vec3::UnitZ()));
            EXPECT_LT(st.pose.orientation.angularDistance(q), 1e-10) << name(regime) << ", frame " << f;
        }
        EXPECT_EQ(be->statistics().at("native.contact_solves"), 0.0) << name(regime);
    }
}

// The schedule: contact_substeps ticks per frame for a resting stack (nothing closes fast).
TEST(NativeFixedTicks, TakesContactSubstepsTicksPerFrame) {
    for (int substeps : {1, 3}) {
        Scene s = bareScene(1e-3);
        const int mat = addMaterial(s, 0.5, 0.2);
        addFloor(s, mat, 20.0);
        for (int i = 0; i < 3; ++i)
            addBody(s, "box" + std::to_string(i), Shape::box(Vec3(0.1, 0.1, 0.1)), at(Vec3(0.0, 0.0, 0.1005 + 0.201 * i)), mat,
                    false, 1.0);
        NativeSettings ns = fixedSettings(TouchingRegime::Fixed);
        ns.contact_substeps = substeps;
        auto be = makeBackend(s, ns);
        for (int f = 0; f < 30; ++f) be->stepFrame(s.frame_dt);
        EXPECT_EQ(be->statistics().at("internal_steps"), 30.0 * substeps);
        EXPECT_NEAR(be->time(), 30 * s.frame_dt, 1e-12);
    }
}

// A domino (0.02 x 0.1 x 0.2 m) tipped 15 deg past balance about its bottom edge falls flat onto the
// floor, turning at up to 10 rad/s: its far edge closes 3-4 cm in a frame. Its landing face is in the
// solve as speculative points before it arrives (the pivot edge both ends and the far edge, even
// while nothing is within the collision distance yet), so no corner sinks below the collision
// distance and nothing is repaired. (Before the patch kept its points with nothing touching, the far
// edge was met 2.2 cm deep; with native.max_fixed_ticks=1, one tick a frame however fast the edge
// closes, 3.5 mm deep.)
TEST(NativeFixedTicks, TippedPlateFallsFlatWithoutSinking) {
    const double cd = 1e-3;
    const Vec3 h(0.01, 0.05, 0.1);
    for (TouchingRegime regime : {TouchingRegime::Fixed, TouchingRegime::FixedSoft}) {
        Scene s = bareScene(cd);
        const int mat = addMaterial(s, 0.6, 0.0);
        addFloor(s, mat, 20.0);
        const double tilt = 15.0 * M_PI / 180.0;
        const Quat q(Eigen::AngleAxisd(tilt, Vec3::UnitY()));
        // The front bottom edge (+x, -z in the body) rests 0.5 mm above the floor.
        const Vec3 edge = q * Vec3(h.x(), 0.0, -h.z());
        const int plate = addBody(s, "plate", Shape::box(h), at(Vec3(0.0, 0.0, 0.5 * cd) - edge, q), mat, false, 0.25);
        auto be = makeBackend(s, fixedSettings(regime));
        double deepest = 0.0;
        for (int f = 0; f < 90; ++f) {
            be->stepFrame(s.frame_dt);
            deepest = std::max(deepest, depthBelowFloor(be->bodyState(plate), h));
        }
        EXPECT_LE(deepest, cd) << name(regime);
        EXPECT_EQ(be->warnings().count("penetration_recovered"), 0u) << name(regime);
        // It lies flat: its thin axis (body x) points up or down.
        const Vec3 thin = be->bodyState(plate).pose.orientation * Vec3::UnitX();
        EXPECT_GT(std::abs(thin.z()), 0.999) << name(regime);
        EXPECT_LT(be->bodyState(plate).linear_velocity.norm(), 1e-2) << name(regime);
    }
}

// Boxes dropped tumbling land and come to rest; fixed ticks hold them within the collision distance.
// A frame is split into up to native.max_fixed_ticks (4) ticks while a pair closes faster than its
// patch reaches: with 1, the boxes land up to 4 cm deep and one is repaired. (Before the contact
// phase's end targets, the looks at a predicted closing and the blow sweeps on fixed ticks, the
// soft solve let them 1.3-1.9 mm deep, and this bound was five collision distances.)
TEST(NativeFixedTicks, TumblingBoxesLandAndRest) {
    const double cd = 1e-3;
    for (std::uint64_t seed : {1u, 2u, 3u}) {
        for (TouchingRegime regime : {TouchingRegime::Fixed, TouchingRegime::FixedSoft}) {
            Scene s = bareScene(cd);
            const int mat = addMaterial(s, 0.1, 0.5);
            addFloor(s, mat, 20.0);
            std::mt19937_64 rng(seed);
            std::uniform_real_distribution<double> u(-1.0, 1.0);
            std::vector<int> boxes;
            std::vector<Vec3> half;
            for (int i = 0; i < 6; ++i) {
                const Vec3 h(0.05 + 0.05 * std::abs(u(rng)), 0.05 + 0.05 * std::abs(u(rng)), 0.02 + 0.08 * std::abs(u(rng)));
                const Quat q(Eigen::AngleAxisd(3.0 * u(rng), Vec3(u(rng), u(rng), u(rng)).normalized()));
                boxes.push_back(addBody(s, "box" + std::to_string(i), Shape::box(h),
                                        at(Vec3(0.6 * (i % 3) - 0.6, 0.6 * (i / 3) - 0.3, 0.4 + 0.2 * std::abs(u(rng))), q),
                                        mat, false, 1.0));
                half.push_back(h);
            }
            auto be = makeBackend(s, fixedSettings(regime));
            double deepest = 0.0;
            for (int f = 0; f < 180; ++f) {
                be->stepFrame(s.frame_dt);
                for (std::size_t k = 0; k < boxes.size(); ++k)
                    deepest = std::max(deepest, depthBelowFloor(be->bodyState(boxes[k]), half[k]));
            }
            EXPECT_LE(deepest, cd) << name(regime) << ", seed " << seed;
            EXPECT_EQ(be->warnings().count("penetration_recovered"), 0u) << name(regime) << ", seed " << seed;
            EXPECT_LE(be->statistics().at("native.deepest_penetration_m"), cd) << name(regime) << ", seed " << seed;
            for (std::size_t k = 0; k < boxes.size(); ++k) {
                // At rest, within the window of the floor.
                EXPECT_LT(be->bodyState(boxes[k]).linear_velocity.norm(), 1e-2) << name(regime) << ", seed " << seed;
                EXPECT_LE(depthBelowFloor(be->bodyState(boxes[k]), half[k]), cd) << name(regime) << ", seed " << seed;
            }
        }
    }
}

// A 5 kg box spinning at 40 rad/s lands at 3 m/s on a 0.2 kg ball resting on the floor. The face
// of the box over the ball turns down onto it at w^2 d (d its distance from the box's centre): about
// 300 m/s^2, so the contact point the tick's solve held is 1-2 mm deep by the tick's end. The pair is
// looked at inside the tick when its points are predicted (to second order, the turning face
// included) to sink half a collision distance below their gap (native.tick_look_depth), and the
// collision phase meets it there: nothing ends deeper than the collision distance (the backend's
// own neutral distance query, every sample) and nothing is repaired. Without those looks
// (tick_look_depth = 0) the check fails: 1.6 mm. The same bits for one worker and two.
TEST(NativeFixedTicks, SpinningBoxOnABallIsLookedAtWhereItsFaceTurnsDown) {
    const double cd = 1e-3, radius = 0.0883;
    Scene s = bareScene(cd);
    const int mat = addMaterial(s, 0.1, 0.5);
    addFloor(s, mat, 2.0);
    vroc::test::addBall(s, "ball", radius, 0.2, Vec3(0.0, 0.0, radius + 0.5 * cd), mat);
    const int box = vroc::test::addBox(s, "box", Vec3(0.0904, 0.0747, 0.0592), 5.0, Vec3(0.0, 0.0, 2.0 * radius + 0.12), mat);
    s.bodies[static_cast<std::size_t>(box)].linear_velocity = Vec3(0.0, 0.0, -3.0);
    s.bodies[static_cast<std::size_t>(box)].angular_velocity = Vec3(0.0, 40.0, 12.0);
    auto deepest = [&](double look_depth, int threads, std::uint64_t* hash) {
        NativeSettings ns = fixedSettings(TouchingRegime::Fixed, threads);
        ns.tick_look_depth = look_depth;
        return deepestOver(s, ns, 90, hash, "look depth " + std::to_string(look_depth));
    };
    std::uint64_t one = 0, two = 0;
    EXPECT_LE(deepest(0.5, 1, &one), cd);
    EXPECT_LE(deepest(0.5, 2, &two), cd);
    EXPECT_EQ(one, two);
    EXPECT_GT(deepest(0.0, 1, nullptr), cd) << "the scene no longer needs the looks: it tests nothing";
}

// A box falling onto a tumbling one turns their edge contact into another face's within a tick:
// the corner that sinks was in no patch, so no manifold point predicts it. The pair's distance
// predicted at the tick's end (native.tick_look_features) finds it, and the pair is looked at when
// it would first sink half a collision distance: nothing ends deeper than the collision distance
// (the backend's own neutral distance query, every sample) and nothing is repaired. Four boxes of
// the 100-box bin (scenes/stress/bin_boxes100.json) as they were at 0.317 s on fixed ticks, where
// that bin went 1.07 mm deep; without those looks this scene goes 1.03 mm deep. The same bits for
// one worker and two.
TEST(NativeFixedTicks, CornerThatNoPatchHeldIsLookedAtBeforeItSinks) {
    const double cd = 1e-3;
    Scene s = bareScene(cd);
    const int mat = addMaterial(s, 0.1, 0.5);
    addFloor(s, mat, 2.5);
    struct Box {
        const char* name;
        Vec3 half, position;
        Quat orientation;
        Vec3 v, w;
    };
    const Box boxes[] = {
        {"boxe05", Vec3(0.0861935, 0.0619909, 0.0683009),
         Vec3(-0.3188364628989655, -0.7097993159461188, 0.07297165796628495),
         Quat(-0.005233532030729029, 0.1604039366092222, -0.9868497580127227, 0.019254671458600808),
         Vec3(0.040728947612795975, -0.423762234902199, -0.22646165510947722),
         Vec3(3.985898173098823, 0.9950231026375986, -1.3016270044059586)},
        {"boxe30", Vec3(0.0550011, 0.0522663, 0.0467316),
         Vec3(-0.3295371348702475, -0.7358739228746486, 0.1986714749064044),
         Quat(0.01435333048374449, 0.9905889134589764, -0.13611300492373282, -0.0009145090601265193),
         Vec3(0.11582569770920512, -0.16860359858122084, -0.7138407328756393),
         Vec3(2.6617834844276644, 0.4819661292386821, -0.8620751536721862)},
        {"boxe35", Vec3(0.0543114, 0.0563948, 0.0796245),
         Vec3(-0.04811735469809389, -0.6468194678096638, 0.16084392844036813),
         Quat(0.2783325172916814, -0.3705374817027881, 0.4643205461086704, -0.7547446024535571),
         Vec3(-0.2651514257000536, 0.5468526502078379, -1.153698718299851),
         Vec3(-17.17278738908341, 1.4587327466928732, -5.939669556030498)},
        {"boxe55", Vec3(0.098601, 0.0878842, 0.0603377), Vec3(-0.379852, -0.710656, 0.3846865),
         Quat(0.4778620819043732, -0.04838200829255598, 0.4103860703391525, -0.7751711328624057),
         Vec3(0.0, 0.0, -3.1065000000000005), Vec3(0.0, 0.0, 0.0)},
    };
    for (const Box& b : boxes) {
        const int i =
            addBody(s, b.name, Shape::box(b.half), at(b.position, b.orientation.normalized()), mat, false, 1.0);
        s.bodies[static_cast<std::size_t>(i)].linear_velocity = b.v;
        s.bodies[static_cast<std::size_t>(i)].angular_velocity = b.w;
    }
    auto deepest = [&](bool features, int threads, std::uint64_t* hash) {
        NativeSettings ns = fixedSettings(TouchingRegime::Fixed, threads);
        ns.tick_look_features = features;
        return deepestOver(s, ns, 6, hash, features ? "feature looks" : "no feature looks");
    };
    std::uint64_t one = 0, two = 0;
    EXPECT_LE(deepest(true, 1, &one), cd);
    EXPECT_LE(deepest(true, 2, &two), cd);
    EXPECT_EQ(one, two);
    EXPECT_GT(deepest(false, 1, nullptr), cd) << "the scene no longer needs the looks: it tests nothing";
}

// A pair apart is not queried, at a tick or in the impact passes after a blow, while its distance
// bound (its last distance, less how far its bodies' points moved since) stays beyond its reach (at
// its bodies' velocities then; native.pair_bounds). The query it skips would have
// found it out of reach: the motion is that of querying every pair at every tick (the second run,
// the independent answer), frame by frame, to rounding, with fewer queries. Not bit for bit: a
// skipped query leaves the pair's walk to start from older features at its next query, and where
// several features are equally close (a box resting flat) the manifold's last bits depend on which
// the walk stops at (on a 100-box bin or the dominoes the final state hashes differ, as they did
// before this test said so). A row of resting boxes 1 cm apart, a box dropped among them and a ball
// rolled into them: pairs apart that stay apart, and pairs apart that close and touch.
TEST(NativeFixedTicks, PairBoundsSkipQueriesNotResults) {
    const double cd = 1e-3, half = 0.1;
    Scene s = bareScene(cd);
    const int mat = addMaterial(s, 0.2, 0.5);
    addFloor(s, mat, 20.0);
    for (int i = 0; i < 6; ++i)
        addBody(s, "box" + std::to_string(i), Shape::box(Vec3(half, half, half)),
                at(Vec3((2 * half + 0.01) * i, 0, half + 0.5 * cd)), mat, false, 1.0);
    addBody(s, "dropped", Shape::box(Vec3(half, half, half)), at(Vec3(0.21 * 2 + 0.105, 0, 1.0)), mat, false, 1.0);
    const int ball = addBody(s, "ball", Shape::sphere(0.08), at(Vec3(-1.0, 0, 0.08 + 0.5 * cd)), mat, false, 2.0);
    s.bodies[static_cast<std::size_t>(ball)].linear_velocity = Vec3(2.0, 0, 0);
    std::vector<std::vector<Vec3>> path(2);   // every body's position at every frame, per run
    std::vector<double> queries, bounded, events;
    for (bool bounds : {true, false}) {
        NativeSettings ns = fixedSettings(TouchingRegime::Fixed);
        ns.pair_bounds = bounds;
        auto be = makeBackend(s, ns);
        for (int f = 0; f < 120; ++f) {
            be->stepFrame(s.frame_dt);
            for (std::size_t b = 0; b < s.bodies.size(); ++b)
                path[bounds ? 0 : 1].push_back(be->bodyState(static_cast<int>(b)).pose.position);
        }
        queries.push_back(be->statistics().at("native.narrow_queries"));
        bounded.push_back(be->statistics().at("native.bounded_pairs"));
        events.push_back(be->statistics().at("collision_events"));
        EXPECT_GT(be->statistics().at("collision_events"), 0.0) << "the ball and the dropped box meet the row";
    }
    double apart = 0.0;
    for (std::size_t k = 0; k < path[0].size(); ++k) apart = std::max(apart, (path[0][k] - path[1][k]).norm());
    EXPECT_LE(apart, 1e-12);
    EXPECT_EQ(events[0], events[1]);
    EXPECT_GT(bounded[0], 0.0);
    EXPECT_EQ(bounded[1], 0.0);
    EXPECT_LT(queries[0], queries[1]);
}

// A 10 kg box at 15 m/s strikes the end of a row of twelve 1 kg boxes 1 cm apart (the row a ball
// smashes in the base-12 pyramid, on a frictionless floor). Within the tick the blow must run the
// whole row: each box it sets moving has its pairs sampled again at once (the impact passes), or a
// box near the far end closes on its neighbour at metres per second with no patch to hold it. Rulers
// independent of the backend: the boxes' x positions (overlap of neighbours) and the momentum.
// The contact phase passes most of the blow on (the collision phase's few sweeps leave a 10:1 chain
// still closing); its impulse on a struck box is applied at once, or the box sinks by half its
// approach over the tick (19 mm without that; 32 mm with 8 impact passes and without it). fixed-soft
// is not held to it: its sub-steps move a box at their mean velocity, and it overlaps by 17 mm here.
TEST(NativeFixedTicks, BlowRunsDownATwelveBoxRow) {
    const double cd = 1e-3, half = 0.25, pitch = 2 * half + 0.01;
    for (TouchingRegime regime : {TouchingRegime::Fixed}) {
        Scene s = bareScene(cd);
        const int mat = addMaterial(s, 0.0, 0.0);
        addFloor(s, mat, 40.0);
        std::vector<int> row;
        row.push_back(addBody(s, "striker", Shape::box(Vec3(half, half, half)), at(Vec3(-0.3, 0, half + 0.5 * cd)), mat,
                              false, 10.0));
        for (int i = 0; i < 12; ++i)
            row.push_back(addBody(s, "box" + std::to_string(i), Shape::box(Vec3(half, half, half)),
                                  at(Vec3(0.3 + pitch * i, 0, half + 0.5 * cd)), mat, false, 1.0));
        s.bodies[static_cast<std::size_t>(row[0])].linear_velocity = Vec3(15.0, 0, 0);
        auto be = makeBackend(s, fixedSettings(regime));
        double overlap = 0.0;
        for (int f = 0; f < 20; ++f) {
            be->stepFrame(s.frame_dt);
            overlap = std::max(overlap, rowOverlap(*be, row, half));
        }
        EXPECT_LE(overlap, 5 * cd) << name(regime);
        EXPECT_EQ(be->warnings().count("penetration_recovered"), 0u) << name(regime);
        double momentum = 0.0;
        for (std::size_t k = 0; k < row.size(); ++k)
            momentum += (k == 0 ? 10.0 : 1.0) * be->bodyState(row[k]).linear_velocity.x();
        EXPECT_NEAR(momentum, 150.0, 0.5) << name(regime) << ": momentum along the row (no friction)";
    }
}

// A pair the tick's broad phase left out is met once a blow sends a body towards it. Ball A rises
// off the floor (its box swept over the tick no longer reaches the floor's); a heavy ball B falls
// onto it from just above at 3 m/s. B's blow sends A down at about 5 m/s within the same tick: the
// impact passes sweep A's box again at its new velocity, so A's pair with the floor is sampled and
// A bounces off the floor in that tick. (Without the new sweep A met the floor a tick later, 48 mm
// deep, and was repaired.) Ruler independent of the backend: A's height over the floor.
TEST(NativeFixedTicks, BlowTowardsAPairTheTickLeftOutIsMet) {
    const double cd = 1e-3, r = 0.05;
    Scene s = bareScene(cd);
    const int mat = addMaterial(s, 0.5, 0.0);
    addFloor(s, mat, 40.0);
    const int a = addBody(s, "a", Shape::sphere(r), at(Vec3(0, 0, r + 3 * cd)), mat, false, 0.2);
    const int b = addBody(s, "b", Shape::sphere(r), at(Vec3(0, 0, 3 * r + 4 * cd)), mat, false, 5.0);
    s.bodies[static_cast<std::size_t>(a)].linear_velocity = Vec3(0, 0, 0.3);
    s.bodies[static_cast<std::size_t>(b)].linear_velocity = Vec3(0, 0, -3.0);
    auto be = makeBackend(s, fixedSettings(TouchingRegime::Fixed));
    double lowest = std::numeric_limits<double>::infinity();
    for (int f = 0; f < 30; ++f) {
        be->stepFrame(s.frame_dt);
        lowest = std::min(lowest, be->bodyState(a).pose.position.z() - r);
    }
    EXPECT_GE(lowest, -cd) << "ball A's lowest point against the floor";
    EXPECT_LE(be->statistics().at("native.deepest_penetration_m"), cd);
    EXPECT_EQ(be->warnings().count("penetration_recovered"), 0u);
    EXPECT_GT(be->statistics().at("native.fixed_impact_passes"), 0.0);
}

// The same bits for any worker count.
TEST(NativeFixedTicks, DeterministicForAnyThreadCount) {
    for (TouchingRegime regime : {TouchingRegime::Fixed, TouchingRegime::FixedSoft}) {
        Scene s = bareScene(1e-3);
        const int mat = addMaterial(s, 0.3, 0.5);
        addFloor(s, mat, 20.0);
        std::mt19937_64 rng(7);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        for (int i = 0; i < 24; ++i) {
            const Quat q(Eigen::AngleAxisd(3.0 * u(rng), Vec3(u(rng), u(rng), u(rng)).normalized()));
            addBody(s, "box" + std::to_string(i), Shape::box(Vec3(0.08, 0.06, 0.04)),
                    at(Vec3(0.25 * u(rng), 0.25 * u(rng), 0.2 + 0.15 * i), q), mat, false, 1.0);
        }
        std::vector<std::uint64_t> hashes;
        for (int threads : {1, 2, 3}) {
            auto be = makeBackend(s, fixedSettings(regime, threads));
            for (int f = 0; f < 90; ++f) be->stepFrame(s.frame_dt);
            hashes.push_back(stateHash(*be));
        }
        EXPECT_EQ(hashes[1], hashes[0]) << name(regime);
        EXPECT_EQ(hashes[2], hashes[0]) << name(regime);
    }
}

// A row of cubes turned 45 degrees about z, without gravity, meeting edge to edge: a chain of
// impacts over two-point patches. Struck at 1 m/s with e = 0.5 (and friction, which has no slip to
// act on), each passes on (1 + e) / 2 of its speed, so the last leaves at 0.75^5 m/s, and nothing
// turns. Both regimes. (On fixed ticks the second impact met a patch at one end of the edge, left by
// a 1e-15 rad turn from the first: the last cube left at 0.13 m/s, spinning.)
TEST(NativeFixedTicks, AChainOfEdgeImpactsPassesItsMomentumOnWithoutTurning) {
    for (TouchingRegime regime : {TouchingRegime::Protected, TouchingRegime::Fixed}) {
        Scene s = bareScene(1e-3, Vec3::Zero());
        const int mat = addMaterial(s, 0.5, 0.5);
        const Quat turned(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitZ()));
        std::vector<int> row;
        for (int i = 0; i < 6; ++i)
            row.push_back(addBody(s, "c" + std::to_string(i), Shape::box(Vec3(0.05, 0.05, 0.05)),
                                  Pose{Vec3(0.25 * i, 0, 0), turned}, mat, false, 1.0));
        s.bodies[static_cast<std::size_t>(row[0])].linear_velocity = Vec3(1.0, 0, 0);
        NativeSettings ns;
        ns.touching = regime;
        auto be = makeBackend(s, ns);
        for (int f = 0; f < 84; ++f) be->stepFrame(s.frame_dt);   // 1.4 s: before any cube catches up again
        const char* label = regime == TouchingRegime::Fixed ? "fixed" : "protected";
        EXPECT_NEAR(be->bodyState(row.back()).linear_velocity.x(), std::pow(0.75, 5), 1e-9) << label;
        for (int c : row) EXPECT_LT(be->bodyState(c).angular_velocity.norm(), 1e-6) << label << ", cube " << c;
    }
}

// Spheres (r = 2.5 cm) fired at 10 to 400 m/s at a real wall 2 cm thick, without gravity, e = 0.5:
// a tick of 1/60 s carries them up to 6.7 m, far past any speculative reach. Each is looked at inside
// the tick when it could first have closed to the collision distance (native.max_tick_looks), meets
// the wall there and leaves at e v, as the closed form says. Its place is the closed form's less at
// most (1 + e) g, g the gap the impact is met at: fixed ticks meet a point that reaches the wall
// within the tick at once, at most its reach (cd + r) early; a look finds the fast ones at cd. With
// no looks (native.max_tick_looks = 0), all from 50 m/s pass through.
TEST(NativeFixedTicks, FastSpheresMeetAThinWallInsideTheTick) {
    const double cd = 1e-3, r = 0.025, e = 0.5, wall = 0.01, start = -1.0, duration = 0.5;
    const std::vector<double> speeds = {10.0, 50.0, 100.0, 200.0, 400.0};
    for (int looks : {64, 0}) {
        Scene s = bareScene(cd, Vec3::Zero());
        const int mat = addMaterial(s, e, 0.3);
        addBody(s, "wall", Shape::box(Vec3(wall, 4.0, 1.0)), at(Vec3::Zero()), mat, true);
        std::vector<int> balls;
        for (std::size_t k = 0; k < speeds.size(); ++k) {
            balls.push_back(addBody(s, "s" + std::to_string(k), Shape::sphere(r), at(Vec3(start, -3.0 + 1.2 * k, 0.0)), mat,
                                    false, 0.1));
            s.bodies[static_cast<std::size_t>(balls.back())].linear_velocity = Vec3(speeds[k], 0.0, 0.0);
        }
        NativeSettings ns = fixedSettings(TouchingRegime::Fixed);
        ns.max_tick_looks = looks;
        auto be = makeBackend(s, ns);
        const int frames = static_cast<int>(std::lround(duration / s.frame_dt));
        for (int f = 0; f < frames; ++f) be->stepFrame(s.frame_dt);
        for (std::size_t k = 0; k < speeds.size(); ++k) {
            const BodyState st = be->bodyState(balls[k]);
            const double v = speeds[k];
            const double hit = (-wall - r - start) / v;   // touching time
            const double x = -wall - r - e * v * (frames * s.frame_dt - hit);
            if (looks > 0) {
                EXPECT_NEAR(st.linear_velocity.x(), -e * v, 1e-9 * v) << v << " m/s";
                EXPECT_LE(st.pose.position.x(), x + 1e-9) << v << " m/s";
                EXPECT_GE(st.pose.position.x(), x - (1.0 + e) * (cd + r)) << v << " m/s";
            } else if (v >= 50.0) {
                EXPECT_GT(st.pose.position.x(), wall) << v << " m/s, no looks: through the wall";
            }
        }
        if (looks > 0) {
            EXPECT_GT(be->statistics().at("native.fixed_tick_looks"), 0.0);
            EXPECT_EQ(be->statistics().at("native.fixed_looks_cut"), 0.0);
            EXPECT_EQ(be->warnings().count("penetration_recovered"), 0u);
        }
    }
}

// A 0.2 kg plate (0.2 x 0.2 x 0.02 m) lies on the floor; a 2 kg ball falls onto it 7 cm from its
// centre at 5 m/s, one tick a frame (native.max_fixed_ticks = 1: 8 cm a tick, eight times the reach
// the plate's thickness allows). The ball is looked at inside the tick as it arrives, and the blow
// is solved there with the plate's contact with the floor, from there to the tick's end. Held to
// five collision distances (the bound TumblingBoxesLandAndRest holds piles to): no plate corner
// deeper below the floor's top, the ball never deeper below the plate's top face, nothing
// repaired. Without the looks the ball lands within the tick through the plate and both sink
// centimetres (56 and 45 mm: the test of the test).
TEST(NativeFixedTicks, PlateStruckByAHeavyBallIsLookedAtInsideTheTick) {
    const double cd = 1e-3, r = 0.05;
    const Vec3 h(0.1, 0.1, 0.01);
    for (int looks : {64, 0}) {
        Scene s = bareScene(cd);
        const int mat = addMaterial(s, 0.2, 0.5);
        addFloor(s, mat, 20.0);
        const int plate = addBody(s, "plate", Shape::box(h), at(Vec3(0.0, 0.0, h.z() + 0.5 * cd)), mat, false, 0.2);
        const int ball = addBody(s, "ball", Shape::sphere(r), at(Vec3(0.07, 0.0, 2.0 * h.z() + r + 0.04)), mat, false, 2.0);
        s.bodies[static_cast<std::size_t>(ball)].linear_velocity = Vec3(0.0, 0.0, -5.0);
        NativeSettings ns = fixedSettings(TouchingRegime::Fixed);
        ns.max_fixed_ticks = 1;
        ns.max_tick_looks = looks;
        auto be = makeBackend(s, ns);
        double plate_depth = 0.0, ball_depth = 0.0;
        for (int f = 0; f < 30; ++f) {
            be->stepFrame(s.frame_dt);
            const BodyState p = be->bodyState(plate), b = be->bodyState(ball);
            plate_depth = std::max(plate_depth, depthBelowFloor(p, h));
            // The ball's centre against the plate's top face plane, over the face.
            const Vec3 local = p.pose.orientation.conjugate() * (b.pose.position - p.pose.position);
            if (std::abs(local.x()) <= h.x() && std::abs(local.y()) <= h.y() && local.z() > 0.0)
                ball_depth = std::max(ball_depth, h.z() + r - local.z());
        }
        if (looks > 0) {
            EXPECT_LE(plate_depth, 5.0 * cd);
            EXPECT_LE(ball_depth, 5.0 * cd);
            EXPECT_EQ(be->warnings().count("penetration_recovered"), 0u);
            EXPECT_GT(be->statistics().at("native.fixed_tick_looks"), 0.0);
        } else {
            EXPECT_GT(std::max(plate_depth, ball_depth), 10.0 * cd) << "no looks";
        }
    }
}

// A ball (r = 0.1 m) dropped from 1 m onto the floor, e = 0.5, one tick a frame or up to four. The
// ball is alone against the floor, so each impact is deferred from the tick's start to its refined
// touching time and met there by a look inside the tick (deferImpacts): each is reported once, at
// the closed form's t1 = sqrt(2 h / g), t1 + 2 e v1 / g, then + 2 e^2 v1 / g (v1 = g t1), within
// 1e-8 s. (Met at the tick's start, before touching, the events were 1-3 ms late; before that,
// never reported at all.)
TEST(NativeFixedTicks, BounceEventsAtTheirTouchingTimes) {
    const double h = 1.0, r = 0.1, e = 0.5, g = 9.81;
    for (int ticks : {1, 4}) {
        int ball = -1;
        const Scene s = dropOntoFloor(Shape::sphere(r), r, h, e, 0.3, ball);
        NativeSettings ns = fixedSettings(TouchingRegime::Fixed);
        ns.max_fixed_ticks = ticks;
        auto be = makeBackend(s, ns);
        std::vector<double> times;
        for (int f = 0; f < 69; ++f) {   // 1.15 s: three impacts, the fourth at 1.242 s
            be->stepFrame(s.frame_dt);
            for (const CollisionEvent& ev : be->takeEvents()) times.push_back(ev.time);
        }
        const double t1 = std::sqrt(2.0 * h / g), v1 = g * t1;
        const std::vector<double> expected = {t1, t1 + 2.0 * e * v1 / g, t1 + 2.0 * e * v1 / g + 2.0 * e * e * v1 / g};
        ASSERT_EQ(times.size(), expected.size()) << ticks << " ticks a frame at most";
        for (std::size_t k = 0; k < expected.size(); ++k)
            EXPECT_NEAR(times[k], expected[k], 1e-8) << "impact " << k << ", " << ticks << " ticks";
    }
}

// A flat box dropped alone onto the floor: its four corners touch at once, at the closed-form time
// t1 = sqrt(2 h / g). Fixed ticks defer the impact from the tick's start to its refined touching time
// and meet it there (a look inside the tick), so the box leaves at e v1 from the floor and rises to
// e^2 h, as the closed form says, without turning. Met at the tick's start instead
// (native.max_tick_looks = 0: no look to defer to), it leaves early and rises about 2 % too high.
TEST(NativeFixedTicks, FlatBoxDroppedAloneBouncesToE2hFromTouching) {
    const double h = 1.0, half = 0.1, e = 0.5, g = 9.81;
    for (int looks : {64, 0}) {
        int box = -1;
        const Scene s = dropOntoFloor(Shape::box(Vec3(half, half, half)), half, h, e, 0.5, box);
        NativeSettings ns = fixedSettings(TouchingRegime::Fixed);
        ns.max_tick_looks = looks;
        auto be = makeBackend(s, ns);
        double apex = -1.0, first = -1.0, spin = 0.0;
        for (int f = 0; f < 48 && apex < 0.0; ++f) {   // the first impact at 0.4515 s, the apex at 0.677 s
            be->stepFrame(s.frame_dt);
            for (const CollisionEvent& ev : be->takeEvents())
                if (first < 0.0) first = ev.time;
            const BodyState st = be->bodyState(box);
            spin = std::max(spin, st.angular_velocity.norm());
            if (first >= 0.0 && st.linear_velocity.z() > 0.0)   // rising: the apex of its exact parabola
                apex = st.pose.position.z() - half + st.linear_velocity.z() * st.linear_velocity.z() / (2.0 * g);
        }
        ASSERT_GT(apex, 0.0) << looks << " looks";
        const double error = std::abs(apex - e * e * h) / (e * e * h);
        if (looks > 0) {
            EXPECT_NEAR(first, std::sqrt(2.0 * h / g), 1e-9);
            EXPECT_LT(error, 1e-6);
            EXPECT_LT(spin, 1e-9);
        } else {
            EXPECT_GT(error, 1e-3);   // the case above is the deferral's doing
        }
    }
}


// A compound of a box and a ball side by side (the conformance landing check's), dropped flat: its
// centre of mass lies between the parts, so no ball about it fits inside the body, and the reach of
// its speculative points is scaled by its thinnest part instead. It lands at the closed-form time
// sqrt(2 h / g), nowhere deeper than the collision distance, and rests. With the reach scaled by
// the COM-centred inner radius (zero) it had no speculative points: it passed 24 mm into the floor
// in one frame and rocked there (41 penetrations repaired, still at 0.3 m/s after 1.5 s).
TEST(NativeFixedTicks, CompoundDroppedFlatLandsAtTouchingAndRests) {
    const double h = 0.1, g = 9.81, cd = 1e-3;
    for (TouchingRegime regime : {TouchingRegime::Fixed, TouchingRegime::FixedSoft}) {
        const Shape shape = Shape::compound({{Shape::box(Vec3(0.1, 0.1, 0.05)), at(Vec3(-0.15, 0, 0))},
                                             {Shape::sphere(0.05), at(Vec3(0.15, 0, 0))}});
        int body = -1;
        const Scene s = dropOntoFloor(shape, 0.05, h, 0.0, 0.5, body);
        auto be = makeBackend(s, fixedSettings(regime));
        double first = -1.0, lowest = std::numeric_limits<double>::infinity();
        for (int f = 0; f < 90; ++f) {
            be->stepFrame(s.frame_dt);
            for (const CollisionEvent& ev : be->takeEvents())
                if (first < 0.0) first = ev.time;
            lowest = std::min(lowest, be->bodyState(body).pose.position.z() - 0.05);
        }
        const BodyState st = be->bodyState(body);
        EXPECT_NEAR(first, std::sqrt(2.0 * h / g), 1e-6) << name(regime);
        EXPECT_GE(lowest, -cd) << name(regime) << ": sank into the floor";
        EXPECT_EQ(be->warnings().count("penetration_recovered"), 0u) << name(regime);
        EXPECT_LE(be->statistics().at("native.deepest_penetration_m"), cd) << name(regime);
        EXPECT_LT(st.linear_velocity.norm() + st.angular_velocity.norm(), 1e-3) << name(regime) << ": still moving";
        EXPECT_NEAR(st.pose.position.z() - 0.05, 0.0, cd) << name(regime);
    }
}

}  // namespace
}  // namespace vroc::native::test
