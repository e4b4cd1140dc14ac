// SPDX-License-Identifier: MIT
// The runner, compare and check logic on two test backends whose trajectories are known in
// closed form: exact flight and semi-implicit Euler (x_euler - x_exact = g dt t / 2).
#include <gtest/gtest.h>

#include <cmath>

#include "harness_test_backends.h"
#include "vroc/core/mass_properties.h"
#include "vroc/harness/check.h"
#include "vroc/harness/compare.h"
#include "vroc/harness/run_trace.h"

namespace vroc::harness {
namespace {

Scene flightScene() {
    Scene s;
    s.name = "flight";
    s.gravity = Vec3(0, 0, -10);
    s.frame_dt = 0.01;
    s.materials.push_back({"m", 0.5, 0.5});
    Body b;
    b.name = "ball";
    b.shape = Shape::sphere(0.1);
    b.mass_properties = massProperties(b.shape, 2.0);
    b.pose.position = Vec3(0, 0, 100);
    b.linear_velocity = Vec3(1, 0, 3);
    s.bodies.push_back(b);
    return s;
}

std::vector<SelectedBackend> testBackends(const std::string& list) {
    harness_test::registerTestBackends();
    return selectBackends(list, {});
}

TEST(HarnessRunner, RecordsEveryFrameAndInvariants) {
    const auto b = testBackends("test-exact");
    RunOptions o;
    o.frame_dt = 0.01;
    o.frames = 100;
    const RunTrace t = runBackend(*b[0].info, flightScene(), b[0].settings, o);
    ASSERT_EQ(t.frames(), 101u);
    ASSERT_EQ(t.step_wall_s.size(), 100u);
    EXPECT_NEAR(t.times.back(), 1.0, 1e-12);
    // Exact flight: z(1) = 100 + 3 - 5 = 98; energy conserved to rounding.
    EXPECT_NEAR(t.states.back()[0].pose.position.z(), 98.0, 1e-9);
    EXPECT_NEAR(t.invariants.back().energy(), t.invariants.front().energy(), 1e-9);
    // record_every keeps every 10th frame and the last.
    o.record_every = 30;
    EXPECT_EQ(runBackend(*b[0].info, flightScene(), b[0].settings, o).frames(), 5u);   // 0, 30, 60, 90, 100
}

TEST(HarnessRunner, InitialStatesGoThroughSetBodyState) {
    const auto b = testBackends("test-exact");
    RunOptions o;
    o.frame_dt = 0.01;
    o.frames = 1;
    std::vector<BodyState> start = initialStates(flightScene());
    start[0].pose.position.x() = 7;
    o.initial_states = start;
    EXPECT_NEAR(runBackend(*b[0].info, flightScene(), b[0].settings, o).states.front()[0].pose.position.x(), 7, 0);
}

TEST(HarnessCompare, DivergenceWindowsAndTwinsMatchTheClosedForm) {
    const auto b = testBackends("test-exact,test-euler");
    CompareOptions o;
    o.duration = 2.0;
    o.window = 0.25;
    o.windows = 5;
    o.progress = false;
    o.write_csv = false;
    const Json doc = compareScene(flightScene(), b, o, {});
    const Json& pair = doc["results"]["pairs"][0];
    const double dt = 0.01, g = 10;
    // |x_euler - x_exact| = g dt t / 2: largest at t = 2 s.
    EXPECT_NEAR(pair["max_divergence_m"].get<double>(), 0.5 * g * dt * 2.0, 1e-9);
    EXPECT_NEAR(pair["final_divergence_m"].get<double>(), 0.5 * g * dt * 2.0, 1e-9);
    // Twins of linear integrators stay 1e-9 apart: no horizon; divergence above the floor from frame 1.
    EXPECT_TRUE(doc["results"]["test-exact"]["twin"]["horizon_s"].is_null());
    EXPECT_NEAR(doc["results"]["test-exact"]["twin"]["final_spread_m"].get<double>(), 1e-9, 1e-12);
    EXPECT_NEAR(pair["first_significant_s"].get<double>(), dt, 1e-12);
    // A window restarted from the exact state: Euler is off by g dt W / 2 after W; exact by ~0.
    for (const Json& e : doc["results"]["test-euler"]["windows"]["position_error_m"]) EXPECT_NEAR(e.get<double>(), 0.5 * g * dt * 0.25, 1e-9);
    for (const Json& e : doc["results"]["test-exact"]["windows"]["position_error_m"]) EXPECT_LT(e.get<double>(), 1e-9);
    // Energy: exact flight conserves it; Euler gains m g (g dt t / 2)... measured against hand value.
    EXPECT_LT(doc["results"]["test-exact"]["invariants"]["energy_max_abs_change_J"].get<double>(), 1e-9);
    EXPECT_EQ(doc["results"]["test-exact"]["events"]["first_contact_s"], nullptr);
    EXPECT_EQ(doc["results"]["test-exact"]["penetration"]["max_m"].get<double>(), 0.0);
    EXPECT_TRUE(doc["results"]["test-euler"]["deterministic"].get<bool>());
    EXPECT_EQ(doc["results"]["test-euler"]["state_hash"].get<std::string>().size(), 16u);
}

TEST(HarnessCheck, ExactFlightPassesBallisticAndEulerFailsItByTheHandValue) {
    const auto b = testBackends("test-exact,test-euler");
    CheckOptions o;
    o.progress = false;
    o.only = {"ballistic", "tumble"};
    const Json doc = runCheckSuite(b, o);
    bool seen = false;
    for (const Json& c : doc["results"]["checks"]) {
        if (c["id"] == "ballistic.position") {
            seen = true;
            EXPECT_TRUE(c["results"]["test-exact"]["pass"].get<bool>()) << c.dump();
            // Euler at 1/240 s over 2 s: g dt t / 2 = 9.81 / 240 = 0.040875 m.
            EXPECT_NEAR(c["results"]["test-euler"]["measured"].get<double>(), 9.81 / 240, 1e-9);
            EXPECT_FALSE(c["results"]["test-euler"]["pass"].get<bool>());
        }
        if (c["id"] == "tumble.angular-momentum") {
            // These backends keep ω constant in the world: no gyroscopic term, so L drifts; the check must see it.
            EXPECT_FALSE(c["results"]["test-exact"]["pass"].get<bool>()) << c.dump();
        }
    }
    EXPECT_TRUE(seen);
    EXPECT_EQ(checkExitCode(doc), 0);   // no backend named native
    EXPECT_NE(checkTableText(doc).find("ballistic.position"), std::string::npos);
}

}  // namespace
}  // namespace vroc::harness
