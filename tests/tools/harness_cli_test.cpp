// SPDX-License-Identifier: MIT
// `vroc check/compare/sweep/report` end to end through the built program, on the Bullet backend
// (skipped when this build has no Bullet), plus the exit-code rule for "native" and native's
// required stress targets.
#include <fstream>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "harness_test_backends.h"
#include "subprocess.h"
#include "test_scenes.h"
#include "vroc/harness/commands/check.h"
#include "vroc/harness/commands/check_suite.h"
#include "vroc/harness/documents/metrics_document.h"

namespace vroc::harness {
namespace {
namespace fs = std::filesystem;

bool haveBullet() {
    static const bool have = test::runVroc({"backends"}, test::freshTempDir("harness-probe")).out.find("bullet") != std::string::npos;
    return have;
}

std::size_t lines(const fs::path& p) {
    std::ifstream in(p);
    std::size_t n = 0;
    for (std::string l; std::getline(in, l);) ++n;
    return n;
}

TEST(HarnessCli, CheckOnBulletWritesTableMetricsAndReport) {
    if (!haveBullet()) GTEST_SKIP() << "no bullet backend in this build";
    const fs::path dir = test::freshTempDir("harness-cli-check");
    const auto r = test::runVroc({"check", "--backends", "bullet", "--only", "ballistic", "--only", "thin-wall", "--out", "out"}, dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;   // no native backend checked: exit 0 whatever bullet does
    EXPECT_NE(r.out.find("ballistic.position"), std::string::npos) << r.out;
    EXPECT_EQ(r.err, "");   // stderr is not a terminal: no progress bar, nothing else
    const Json doc = readDocument(dir / "out" / "metrics.json");
    ASSERT_EQ(doc["results"]["checks"].size(), 5u);  // ballistic x3 (one reported), thin wall x2
    for (const Json& c : doc["results"]["checks"]) {
        const Json& res = c["results"]["bullet"];
        if (res["pass"].is_null()) {  // reported, not judged: ballistic.euler-ratio
            EXPECT_TRUE(c["tolerance"].is_null()) << c.dump();
            continue;
        }
        const bool pass = res["pass"].get<bool>();
        // pass is exactly |measured - expected| <= tolerance
        if (!res["measured"].is_null()) {
            EXPECT_EQ(pass, std::abs(res["measured"].get<double>() - c["expected"].get<double>()) <= c["tolerance"].get<double>()) << c.dump();
        }
        EXPECT_NE(r.out.find(c["id"].get<std::string>()), std::string::npos);
    }
    EXPECT_TRUE(fs::exists(dir / "out" / "report.html"));
}

TEST(HarnessCli, ExitCodeOneOnlyWhenNativeFailsARequiredCheck) {
    harness_test::registerTestBackends();
    // A stand-in registered as "native" in this test process only: flight that keeps omega constant
    // in the world (no gyroscopic term), which fails the required tumble checks.
    if (!BackendRegistry::global().find("native")) {
        BackendInfo info = *BackendRegistry::global().find("test-euler");
        info.name = "native";
        BackendRegistry::global().add(info);
    }
    CheckOptions o;
    o.progress = false;
    o.only = {"tumble"};
    EXPECT_EQ(runCheckSuite(selectBackends("test-exact,native", {}), o).exitCode(), 1);
    EXPECT_EQ(runCheckSuite(selectBackends("test-euler", {}), o).exitCode(), 0);  // not named native
}

// Issue 22: native's stress targets are required, so a regression fails the default suite. The
// stress section on native alone (every stress scene; about 20 s on one core, 14 s on two).
TEST(HarnessCli, NativeMeetsEveryRequiredStressTarget) {
    const fs::path dir = test::freshTempDir("harness-cli-stress");
    std::vector<std::string> args = {"check",        "--stress",
                                     "--backends",   "native",
                                     "--scenes-dir", (fs::path(VROC_SOURCE_DIR) / "scenes" / "stress").string(),
                                     "--out",        "out"};
    for (const std::string& id : stressScenarioIds()) {
        args.push_back("--only");
        args.push_back(id);
    }
    std::string command = "vroc";
    for (const std::string& a : args) command += " " + a;
    const auto r = test::runVroc(args, dir);
    ASSERT_EQ(r.exit_code, 0) << "reproduce: " << command << "\n" << r.out << r.err;
    const Json doc = readDocument(dir / "out" / "metrics.json");
    EXPECT_EQ(doc["results"]["required_failures_native"].get<int>(), 0);
    // Every stress scene ran, each with required targets that native passed.
    std::set<std::string> scenes;
    for (const Json& c : doc["results"]["checks"])
        if (c["required_for_native"].get<bool>()) {
            scenes.insert(c["scenario"].get<std::string>());
            EXPECT_TRUE(c["results"]["native"]["pass"].get<bool>()) << c.dump();
        }
    EXPECT_EQ(scenes.size(), stressScenarioIds().size()) << r.out;
}

TEST(HarnessCli, CompareThenReportOnBullet) {
    if (!haveBullet()) GTEST_SKIP() << "no bullet backend in this build";
    const fs::path dir = test::freshTempDir("harness-cli-compare");
    test::writeFile(dir / "two.json", test::kTwoBodyScene);
    const auto r = test::runVroc({"compare", "two.json", "--backends", "bullet", "--duration", "1", "--out", "cmp"}, dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Json doc = readDocument(dir / "cmp" / "metrics.json");
    const Json& b = doc["results"]["bullet"];
    EXPECT_GT(b["timing"]["p50_us"].get<double>(), 0);
    EXPECT_GE(b["penetration"]["max_m"].get<double>(), 0);
    EXPECT_EQ(doc["parameters"]["frames"].get<int>(), 100);
    EXPECT_EQ(lines(dir / "cmp" / "bullet" / "trajectory.csv"), 1u + 101u * 2u);   // header + frames x virtual bodies
    EXPECT_EQ(lines(dir / "cmp" / "bullet" / "step_times.csv"), 1u + 100u);
    fs::remove(dir / "cmp" / "report.html");
    const auto rep = test::runVroc({"report", "cmp"}, dir);
    ASSERT_EQ(rep.exit_code, 0) << rep.err;
    EXPECT_TRUE(fs::exists(dir / "cmp" / "report.html"));
}

TEST(HarnessCli, SweepMarksAParetoFront) {
    if (!haveBullet()) GTEST_SKIP() << "no bullet backend in this build";
    const fs::path dir = test::freshTempDir("harness-cli-sweep");
    const auto r = test::runVroc({"sweep", "check:bounce-e0.8", "--backends", "bullet", "--dt", "1/60,1/120,1/240",
                                  "--duration", "1", "--windows", "3", "--out", "sw"}, dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Json doc = readDocument(dir / "sw" / "metrics.json");
    const Json& steps = doc["results"]["bullet"]["steps"];
    EXPECT_EQ(steps.size(), 5u);   // 3 measured + 2 robustness-only (1/30, 1/15)
    ASSERT_FALSE(doc["results"]["pareto_front"].empty());
    // The front is non-dominated: no measured point is both cheaper and more accurate than a front point.
    for (const Json& f : doc["results"]["pareto_front"])
        for (const Json& s : steps) {
            if (!s.contains("cost_wall_per_sim_s") || s["window_error_m"].is_null()) continue;
            EXPECT_FALSE(s["cost_wall_per_sim_s"].get<double>() < f["cost_wall_per_sim_s"].get<double>() &&
                         s["window_error_m"].get<double>() < f["window_error_m"].get<double>());
        }
}

TEST(HarnessCli, BadInputIsOneLineExitTwo) {
    const fs::path dir = test::freshTempDir("harness-cli-bad");
    auto r = test::runVroc({"check", "--backends", "nope"}, dir);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("unknown backend 'nope'"), std::string::npos) << r.err;
    r = test::runVroc({"sweep", "check:no-such", "--backends", "test"}, dir);
    EXPECT_EQ(r.exit_code, 2);
    r = test::runVroc({"sweep", "check:ballistic", "--dt", "1/0"}, dir);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--dt"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace vroc::harness
