// SPDX-License-Identifier: MIT
// A run in which the engine dropped contacts (a full buffer) is not the engine's physics: compare,
// check and sweep mark it not valid, with the reason, and keep it out of every verdict. The
// dropping backend flies exactly like test-exact, so any verdict that still counted it would
// have it agree with test-exact: each test below fails if the mark is lost.
#include <algorithm>

#include <gtest/gtest.h>

#include "harness_test_backends.h"
#include "vroc/harness/commands/check.h"
#include "vroc/harness/commands/compare.h"
#include "vroc/harness/commands/sweep.h"
#include "vroc/harness/documents/check_document.h"
#include "vroc/harness/documents/compare_document.h"
#include "vroc/harness/documents/sweep_document.h"
#include "vroc/harness/runs/run_validity.h"

namespace vroc::harness {
namespace {

using harness_test::flightScene;

std::vector<SelectedBackend> backends(const std::string& list) { return harness_test::testBackends(list); }

bool contains(const std::vector<std::string>& v, const std::string& x) {
    return std::find(v.begin(), v.end(), x) != v.end();
}

TEST(RunValidity, DroppedContactsMakeARunNotValidAndSayHowOften) {
    EXPECT_TRUE(runValidity(WarningCounts{}, true).valid);
    EXPECT_TRUE(runValidity(WarningCounts{{"contacts_dropped", 0}}, true).valid);
    const RunValidity v = runValidity(WarningCounts{{"contacts_dropped", 17}}, true);
    EXPECT_FALSE(v.valid);
    EXPECT_NE(v.reason.find("17"), std::string::npos) << v.reason;
    EXPECT_NE(v.reason.find("contacts_dropped"), std::string::npos) << v.reason;
    EXPECT_EQ(invalidLabel(v).rfind("not valid: ", 0), 0u);
    EXPECT_FALSE(runValidity(WarningCounts{}, false).valid);
}

TEST(RunValidity, CompareMarksTheRunAndLeavesItOutOfTheConsensus) {
    CompareOptions o;
    o.duration = 0.5;
    o.windows = 2;
    o.window = 0.1;
    o.progress = false;
    o.write_csv = false;
    const CompareResult c = compareScene(flightScene(), backends("test-exact,test-euler,test-dropping"), o, {});
    ASSERT_EQ(c.summaries.size(), 3u);
    EXPECT_TRUE(c.summaries[0].validity.valid);
    EXPECT_TRUE(c.summaries[1].validity.valid);
    EXPECT_FALSE(c.summaries[2].validity.valid);
    for (const ConsensusRow& row : c.consensus) {
        EXPECT_FALSE(contains(row.result.agreeing, "test-dropping")) << row.observable;
        EXPECT_FALSE(contains(row.result.outliers, "test-dropping")) << row.observable;
        const bool named =
            std::any_of(row.result.left_out.begin(), row.result.left_out.end(),
                        [](const std::string& l) { return l.rfind("test-dropping: not valid: ", 0) == 0; });
        EXPECT_TRUE(named) << row.observable;
    }
    const Json doc = compareDocument(c, "vroc compare");
    EXPECT_EQ(doc["results"]["test-dropping"]["valid"], false);
    EXPECT_EQ(doc["results"]["test-exact"]["valid"], true);
    ASSERT_TRUE(doc.contains("summary"));
    EXPECT_NE(doc["summary"].get<std::string>().find("test-dropping"), std::string::npos);
    const std::string table = doc["tables"].dump();
    EXPECT_NE(table.find("test-dropping (not valid"), std::string::npos);
    EXPECT_NE(table.find("test-exact vs test-dropping (not valid: test-dropping)"), std::string::npos);
}

TEST(RunValidity, CheckReportsNotValidCellsUnjudged) {
    CheckOptions o;
    o.progress = false;
    o.only = {"ballistic"};
    const CheckSuiteResult r = runCheckSuite(backends("test-exact,test-dropping"), o);
    ASSERT_FALSE(r.rows.empty());
    for (const CheckRow& row : r.rows) {
        EXPECT_TRUE(row.cells[0].validity.valid);
        EXPECT_FALSE(row.cells[1].validity.valid);
        EXPECT_FALSE(row.cells[1].pass.has_value()) << row.metric.id;  // exact flight would pass: it is not judged
        if (row.metric.judged()) {
            EXPECT_EQ(row.cells[0].pass, true) << row.metric.id;
        }
    }
    const std::string text = checkTableText(r);
    EXPECT_NE(text.find("n/v"), std::string::npos) << text;
    EXPECT_NE(text.find("test-dropping: ballistic n/v: the engine dropped contacts"), std::string::npos) << text;
}

TEST(RunValidity, ASweepPointThatIsNotValidIsNeverOnTheParetoFront) {
    SweepOptions o;
    o.dts = {1.0 / 60, 1.0 / 120};
    o.duration = 0.5;
    o.windows = 2;
    o.window = 0.1;
    o.robustness_extra = 0;
    o.progress = false;
    SweepScene s{flightScene(), std::nullopt, "flight"};
    RunPool pool = RunPool::inProcess();
    const SweepResult r = runSweep(s, backends("test-dropping,test-euler"), o, pool);
    bool any_front = false;
    for (const SweepPoint& p : r.points) {
        const SweepStep& step = r.stepOf(p);
        const bool dropping = r.curves[p.curve].curve.run.info->name == "test-dropping";
        EXPECT_EQ(step.not_valid.empty(), !dropping);
        if (dropping) {
            EXPECT_FALSE(p.on_pareto_front);  // exact flight: zero error, it would dominate
        }
        any_front = any_front || p.on_pareto_front;
    }
    EXPECT_TRUE(any_front);
    EXPECT_NE(sweepDocument(r, "vroc sweep")["tables"].dump().find("not valid: the engine dropped contacts"),
              std::string::npos);
}

}  // namespace
}  // namespace vroc::harness
