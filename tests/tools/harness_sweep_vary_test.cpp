// SPDX-License-Identifier: MIT
// `vroc sweep --vary KEY=V1,V2,...`: one curve per value, in metrics.json and in the chart data
// gnuplot read; a bad key or value is one line and exit 2. Runs the built program on Bullet
// (skipped when this build has no Bullet).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <set>

#include "subprocess.h"
#include "test_scenes.h"
#include "vroc/harness/documents/metrics_document.h"

namespace vroc::harness {
namespace {
namespace fs = std::filesystem;

bool haveBullet() {
    static const bool have = test::runVroc({"backends"}, test::freshTempDir("sweep-vary-probe")).out.find("bullet") != std::string::npos;
    return have;
}

// Point counts of the index blocks of a gnuplot data file ("x y" rows, blocks split by two blank lines).
std::vector<std::size_t> blockSizes(const fs::path& p) {
    std::ifstream in(p);
    std::vector<std::size_t> sizes;
    int blanks = 2;
    for (std::string line; std::getline(in, line);) {
        if (line.empty()) { ++blanks; continue; }
        if (line[0] == '#') continue;
        if (blanks >= 2) sizes.push_back(0);
        blanks = 0;
        ++sizes.back();
    }
    return sizes;
}

TEST(HarnessSweepVary, OneSeriesPerValueInMetricsAndChart) {
    if (!haveBullet()) GTEST_SKIP() << "no bullet backend in this build";
    const fs::path dir = test::freshTempDir("harness-sweep-vary");
    const auto r = test::runVroc({"sweep", "check:bounce-e0.8", "--backends", "bullet", "--dt", "1/60,1/120", "--duration", "1",
                                  "--windows", "2", "--vary", "bullet.solver_iterations=5,50", "--vary", "bullet.substeps=2",
                                  "--out", "sw", "--quiet"}, dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Json doc = readDocument(dir / "sw" / "metrics.json");
    const std::vector<std::string> labels = {"bullet solver_iterations=5", "bullet solver_iterations=50", "bullet substeps=2"};
    EXPECT_FALSE(doc["results"].contains("bullet"));   // every bullet curve is a varied one
    for (const std::string& l : labels) {
        ASSERT_TRUE(doc["results"].contains(l)) << doc["results"].dump();
        EXPECT_EQ(doc["results"][l]["backend"], "bullet");
        EXPECT_EQ(l, "bullet " + doc["results"][l]["setting"].get<std::string>());
        std::size_t measured = 0;
        for (const Json& s : doc["results"][l]["steps"]) measured += s.contains("cost_wall_per_sim_s");
        EXPECT_EQ(measured, 2u) << l;   // one point per --dt value
    }
    // The speed-accuracy chart: one series per curve in order, then the Pareto front; the data
    // file gnuplot read has the same blocks with the same point counts.
    const Json* chart = nullptr;
    for (const Json& c : doc["charts"]) if (c["id"] == "speed-accuracy") chart = &c;
    ASSERT_NE(chart, nullptr);
    ASSERT_EQ((*chart)["series"].size(), labels.size() + 1);
    for (std::size_t i = 0; i < labels.size(); ++i) {
        EXPECT_EQ((*chart)["series"][i]["name"], labels[i]);
        EXPECT_EQ((*chart)["series"][i]["x"].size(), 2u) << labels[i];
    }
    const auto blocks = blockSizes(dir / "sw" / "charts" / "d0-speed-accuracy.dat");
    ASSERT_EQ(blocks.size(), (*chart)["series"].size());
    for (std::size_t i = 0; i < blocks.size(); ++i) EXPECT_EQ(blocks[i], (*chart)["series"][i]["x"].size()) << i;
    // The Pareto front names its series, each one of the curves.
    for (const Json& f : doc["results"]["pareto_front"])
        EXPECT_TRUE(std::set<std::string>(labels.begin(), labels.end()).count(f["series"].get<std::string>())) << f.dump();
}

TEST(HarnessSweepVary, BadKeyOrValueIsExitTwo) {
    const fs::path dir = test::freshTempDir("harness-sweep-vary-bad");
    auto r = test::runVroc({"sweep", "check:ballistic", "--vary", "nope.x=1"}, dir);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--vary nope.x=1"), std::string::npos) << r.err;
    if (!haveBullet()) GTEST_SKIP() << "no bullet backend in this build";
    r = test::runVroc({"sweep", "check:ballistic", "--backends", "bullet", "--vary", "bullet.no_such_key=1,2"}, dir);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("unknown key 'bullet.no_such_key'"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("bullet.solver_iterations"), std::string::npos) << r.err;   // lists the valid keys
    r = test::runVroc({"sweep", "check:ballistic", "--backends", "bullet", "--vary", "bullet.solver_iterations=5,0"}, dir);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--vary bullet.solver_iterations=0"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "runs"));   // failed before writing anything
}

}  // namespace
}  // namespace vroc::harness
