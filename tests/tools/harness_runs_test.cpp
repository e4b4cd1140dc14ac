// SPDX-License-Identifier: MIT
// The runner, compare and check logic on two test backends whose trajectories are known in
// closed form: exact flight and semi-implicit Euler (x_euler - x_exact = g dt t / 2).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "harness_test_backends.h"
#include "vroc/core/mass_properties.h"
#include "vroc/harness/commands/check.h"
#include "vroc/harness/commands/compare.h"
#include "vroc/harness/documents/check_document.h"
#include "vroc/harness/documents/compare_document.h"
#include "vroc/harness/runs/run_trace.h"

namespace vroc::harness {
namespace {

using harness_test::flightScene;
using harness_test::testBackends;

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
    const CompareResult c = compareScene(flightScene(), b, o, {});
    ASSERT_EQ(c.pairs.size(), 1u);
    const ComparePair& pair = c.pairs[0];
    const CompareBackendSummary& exact = c.summaries[0];
    const CompareBackendSummary& euler = c.summaries[1];
    const double dt = 0.01, g = 10;
    // |x_euler - x_exact| = g dt t / 2: largest at t = 2 s.
    EXPECT_NEAR(*std::max_element(pair.divergence.distance.begin(), pair.divergence.distance.end()), 0.5 * g * dt * 2.0, 1e-9);
    EXPECT_NEAR(pair.divergence.distance.back(), 0.5 * g * dt * 2.0, 1e-9);
    // Twins of linear integrators stay 1e-9 apart: no horizon; divergence above the floor from frame 1.
    EXPECT_FALSE(exact.horizon.has_value());
    EXPECT_NEAR(exact.twin_spread.distance.back(), 1e-9, 1e-12);
    ASSERT_TRUE(pair.significance.first_time.has_value());
    EXPECT_NEAR(*pair.significance.first_time, dt, 1e-12);
    // A window restarted from the exact state: Euler is off by g dt W / 2 after W; exact by ~0.
    ASSERT_EQ(euler.window_position_error.size(), 5u);
    for (double e : euler.window_position_error) EXPECT_NEAR(e, 0.5 * g * dt * 0.25, 1e-9);
    for (double e : exact.window_position_error) EXPECT_LT(e, 1e-9);
    // Energy: exact flight conserves it.
    EXPECT_LT(exact.invariants.energy_max_abs_change, 1e-9);
    EXPECT_FALSE(exact.events.first_contact.has_value());
    EXPECT_EQ(exact.penetration_max, 0.0);
    EXPECT_TRUE(c.runs[1].deterministic);
    EXPECT_EQ(c.runs[1].state_hash.size(), 16u);
    // The document is written from the same result, under the documented keys.
    const Json doc = compareDocument(c, "vroc compare");
    EXPECT_NEAR(doc["results"]["pairs"][0]["max_divergence_m"].get<double>(), 0.5 * g * dt * 2.0, 1e-9);
    EXPECT_TRUE(doc["results"]["test-exact"]["twin"]["horizon_s"].is_null());
    EXPECT_EQ(doc["results"]["test-exact"]["events"]["first_contact_s"], nullptr);
    EXPECT_EQ(doc["results"]["test-euler"]["windows"]["position_error_m"].size(), 5u);
    EXPECT_EQ(doc["results"]["test-euler"]["state_hash"], c.runs[1].state_hash);
}

TEST(HarnessCheck, ExactFlightPassesBallisticAndEulerFailsItByTheHandValue) {
    const auto b = testBackends("test-exact,test-euler");
    CheckOptions o;
    o.progress = false;
    o.only = {"ballistic", "tumble"};
    const CheckSuiteResult result = runCheckSuite(b, o);
    bool seen = false;
    for (const CheckRow& row : result.rows) {
        if (row.metric.id == "ballistic.position") {
            seen = true;
            EXPECT_EQ(row.cells[0].pass, true);
            // Euler at 1/240 s over 2 s: g dt t / 2 = 9.81 / 240 = 0.040875 m: a first-order step's
            // own error, which passes (the order is reported, not failed).
            EXPECT_NEAR(row.cells[1].measured, 9.81 / 240, 1e-9);
            EXPECT_EQ(row.cells[1].pass, true);
        }
        if (row.metric.id == "ballistic.euler-ratio") {  // reported: 0 exact, 1 first order
            EXPECT_FALSE(row.metric.judged());
            EXPECT_NEAR(row.cells[0].measured, 0.0, 1e-9);
            EXPECT_NEAR(row.cells[1].measured, 1.0, 1e-9);
        }
        if (row.metric.id == "tumble.angular-momentum") {
            // These backends keep ω constant in the world: no gyroscopic term, so L drifts; the check must see it.
            EXPECT_EQ(row.cells[0].pass, false) << row.cells[0].measured;
        }
    }
    EXPECT_TRUE(seen);
    EXPECT_EQ(result.exitCode(), 0);   // no backend named native
    EXPECT_NE(checkTableText(result).find("ballistic.position"), std::string::npos);
    // The document is written from the same result: the cells by backend name.
    const Json doc = checkDocument(result, "vroc check");
    ASSERT_EQ(doc["results"]["checks"].size(), result.rows.size());
    const Json& first = doc["results"]["checks"][0];
    EXPECT_EQ(first["id"], result.rows[0].metric.id);
    EXPECT_EQ(first["results"]["test-euler"]["measured"].get<double>(), result.rows[0].cells[1].measured);
    EXPECT_EQ(first["results"]["test-exact"]["support"], "exact");
}

}  // namespace
}  // namespace vroc::harness
