// SPDX-License-Identifier: MIT
// `vroc backends` and `vroc run` as a user runs them: files, headers, initial state, row counts,
// run.json fields, determinism, --help.
#include <cmath>
#include <filesystem>
#include <set>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "csv_reader.h"
#include "subprocess.h"
#include "test_scenes.h"

namespace vroc::test {
namespace {
namespace fs = std::filesystem;

struct CliRun : ::testing::Test {
    void SetUp() override {
        dir = freshTempDir(std::string("cli-") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        scene_file = writeFile(dir / "two_bodies.json", kTwoBodyScene);
        scene = nlohmann::json::parse(kTwoBodyScene);
    }
    void TearDown() override { fs::remove_all(dir); }
    fs::path dir;
    fs::path scene_file;
    nlohmann::json scene;
};

TEST_F(CliRun, BackendsListsBulletWithVersionAndSettings) {
    const auto r = runVroc({"backends"}, dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("bullet  Bullet"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("bullet.substeps"), std::string::npos) << r.out;
    EXPECT_EQ(r.err, "");
    const auto names = runVroc({"backends", "--names"}, dir);
    const auto lines = splitLines(names.out);
    EXPECT_NE(std::find(lines.begin(), lines.end(), "bullet"), lines.end()) << names.out;
}

TEST_F(CliRun, HelpIsCompleteAndExitsZero) {
    auto r = runVroc({"--help"}, dir);
    EXPECT_EQ(r.exit_code, 0);
    for (const char* word : {"backends", "run", "Exit codes"}) EXPECT_NE(r.out.find(word), std::string::npos) << word;
    r = runVroc({"run", "--help"}, dir);
    EXPECT_EQ(r.exit_code, 0);
    for (const char* word : {"--backend", "--duration", "--dt", "--out", "--set", "--quiet", "scene"})
        EXPECT_NE(r.out.find(word), std::string::npos) << word << "\n" << r.out;
    r = runVroc({"backends", "--help"}, dir);
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_NE(r.out.find("--names"), std::string::npos);
}

TEST_F(CliRun, WritesThreeFilesWithExactHeadersInitialStateAndRowCounts) {
    const auto r = runVroc({"run", scene_file.string(), "--backend", "bullet", "--dt", "0.02", "--duration", "0.5",
                            "--out", "out"}, dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err, "");   // stderr is not a terminal: no progress bar
    const fs::path out = dir / "out";
    const auto trajectory = splitLines(readText((out / "trajectory.csv").string()));
    const auto events = splitLines(readText((out / "events.csv").string()));
    ASSERT_FALSE(trajectory.empty());
    ASSERT_FALSE(events.empty());
    EXPECT_EQ(trajectory[0], "t,body,x,y,z,qx,qy,qz,qw,vx,vy,vz,wx,wy,wz");
    EXPECT_EQ(events[0], "t,body_a,body_b,px,py,pz,nx,ny,nz,impulse");
    // 0.5 s / 0.02 s = 25 steps, 2 virtual bodies, plus the t = 0 frame.
    EXPECT_EQ(trajectory.size(), 1u + 2u * (25u + 1u));

    // t = 0 rows: exactly the scene's virtual bodies, in order, at their initial state.
    const auto& bodies = scene["bodies"];
    for (int k = 0; k < 2; ++k) {
        const auto row = splitCsv(trajectory[1 + k]);
        const auto& body = bodies[1 + k];
        ASSERT_EQ(row.size(), 15u);
        EXPECT_EQ(row[0], "0");
        EXPECT_EQ(row[1], body["name"]);
        const std::vector<double> q = body.contains("orientation") ? body["orientation"].get<std::vector<double>>()
                                                                   : std::vector<double>{0, 0, 0, 1};
        for (int i = 0; i < 3; ++i) {
            EXPECT_NEAR(std::stod(row[2 + i]), body["position"][i].get<double>(), 1e-12) << trajectory[1 + k];
            EXPECT_NEAR(std::stod(row[9 + i]), body["linear_velocity"][i].get<double>(), 1e-12) << trajectory[1 + k];
            EXPECT_NEAR(std::stod(row[12 + i]), body["angular_velocity"][i].get<double>(), 1e-12) << trajectory[1 + k];
        }
        for (int i = 0; i < 4; ++i) EXPECT_NEAR(std::stod(row[5 + i]), q[i], 1e-12) << trajectory[1 + k];
    }
    // Frames advance by dt and every row is finite.
    const auto last = splitCsv(trajectory.back());
    EXPECT_NEAR(std::stod(last[0]), 0.5, 1e-12);
    for (std::size_t i = 1; i < trajectory.size(); ++i)
        for (const auto& field : splitCsv(trajectory[i])) {
            if (field == "ball" || field == "box") continue;
            EXPECT_TRUE(std::isfinite(std::stod(field))) << trajectory[i];
        }
    // The ball falls from 0.6 m and lands within 0.5 s: at least one floor-ball collision.
    bool ball_hit_floor = false;
    for (std::size_t i = 1; i < events.size(); ++i) {
        const auto e = splitCsv(events[i]);
        ASSERT_EQ(e.size(), 10u) << events[i];
        ball_hit_floor = ball_hit_floor || (e[1] == "floor" && e[2] == "ball");
    }
    EXPECT_TRUE(ball_hit_floor) << readText((out / "events.csv").string());
}

TEST_F(CliRun, RunJsonHasEveryFieldAndTwoRunsHashTheSame) {
    const auto a = runVroc({"run", scene_file.string(), "--backend", "bullet", "--out", "a", "--quiet",
                            "--duration", "1", "--set", "bullet.substeps=2"}, dir);
    const auto b = runVroc({"run", scene_file.string(), "--backend", "bullet", "--out", "b", "--quiet",
                            "--duration", "1", "--set", "bullet.substeps=2"}, dir);
    ASSERT_EQ(a.exit_code, 0) << a.err;
    ASSERT_EQ(b.exit_code, 0) << b.err;
    EXPECT_EQ(a.out + a.err, "");   // --quiet: nothing at all
    const auto ja = nlohmann::json::parse(readText((dir / "a" / "run.json").string()));
    const auto jb = nlohmann::json::parse(readText((dir / "b" / "run.json").string()));
    for (const char* key : {"format", "scene", "backend", "settings", "frame_dt", "duration", "steps", "simulated_time",
                            "start_time_utc", "wall_time_s", "step_wall_time_us", "collision_count", "pair_count",
                            "warnings", "statistics", "state_hash", "build", "command_line"})
        EXPECT_TRUE(ja.contains(key)) << key;
    EXPECT_EQ(ja["scene"]["name"], "two_bodies");
    EXPECT_EQ(ja["scene"]["sha256"].get<std::string>().size(), 64u);
    EXPECT_EQ(ja["backend"]["name"], "bullet");
    EXPECT_EQ(ja["settings"]["bullet.substeps"], "2");
    EXPECT_EQ(ja["frame_dt"], 0.01);   // the scene's frame_dt
    EXPECT_EQ(ja["steps"], 100);
    for (const char* key : {"version", "commit", "compiler", "flags"}) EXPECT_TRUE(ja["build"].contains(key)) << key;
    for (const char* key : {"p50", "p90", "p99"}) EXPECT_GT(ja["step_wall_time_us"][key].get<double>(), 0) << key;
    EXPECT_LE(ja["step_wall_time_us"]["p50"].get<double>(), ja["step_wall_time_us"]["p99"].get<double>());
    EXPECT_EQ(ja["state_hash"].get<std::string>().size(), 16u);
    EXPECT_EQ(ja["state_hash"], jb["state_hash"]);
    // The hash summarises the state: the trajectories agree byte for byte too.
    EXPECT_EQ(readText((dir / "a" / "trajectory.csv").string()), readText((dir / "b" / "trajectory.csv").string()));
    // Collision count is the number of rows in events.csv.
    EXPECT_EQ(ja["collision_count"].get<std::size_t>() + 1,
              splitLines(readText((dir / "a" / "events.csv").string())).size());
}

TEST_F(CliRun, DefaultOutputDirectoryIsUnderRunsAndNamedAfterSceneAndBackend) {
    const auto r = runVroc({"run", scene_file.string(), "--backend", "bullet", "--duration", "0.1"}, dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::vector<fs::path> runs;
    for (const auto& entry : fs::directory_iterator(dir / "runs")) runs.push_back(entry.path());
    ASSERT_EQ(runs.size(), 1u);
    EXPECT_EQ(runs[0].filename().string().rfind("two_bodies-bullet-", 0), 0u) << runs[0];
    EXPECT_TRUE(fs::exists(runs[0] / "run.json"));
    EXPECT_NE(r.out.find(runs[0].lexically_normal().string()), std::string::npos) << r.out;   // absolute path printed
}

TEST_F(CliRun, SetIsRepeatableAndTakesOneValueEach) {
    // --set before the scene must not swallow it; the last assignment of a key wins.
    const auto r = runVroc({"run", "--set", "bullet.substeps=3", "--set", "bullet.ccd=false", "--set",
                            "bullet.substeps=5", scene_file.string(), "-b", "bullet", "-o", "s", "-q",
                            "--duration", "0.05"}, dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(readText((dir / "s" / "run.json").string()));
    EXPECT_EQ(j["settings"]["bullet.substeps"], "5");
    EXPECT_EQ(j["settings"]["bullet.ccd"], "false");
    EXPECT_EQ(j["settings"]["bullet.margin"], "0.04");   // untouched keys keep their defaults
}

TEST_F(CliRun, RunningAgainIntoTheSameDirectoryReplacesTheRun) {
    ASSERT_EQ(runVroc({"run", scene_file.string(), "-b", "bullet", "-o", "same", "-q", "--duration", "0.2"}, dir).exit_code, 0);
    ASSERT_EQ(runVroc({"run", scene_file.string(), "-b", "bullet", "-o", "same", "-q", "--duration", "0.1"}, dir).exit_code, 0);
    const auto j = nlohmann::json::parse(readText((dir / "same" / "run.json").string()));
    EXPECT_EQ(j["steps"], 10);
    EXPECT_EQ(splitLines(readText((dir / "same" / "trajectory.csv").string())).size(), 1u + 2u * 11u);
}

}  // namespace
}  // namespace vroc::test
