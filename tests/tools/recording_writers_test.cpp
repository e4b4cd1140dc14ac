// SPDX-License-Identifier: MIT
// Unit tests of the recording writers: CSV layout and exactness, atomic files, run.json, timings.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "csv_reader.h"
#include "test_scenes.h"
#include "vroc/core/errors.h"
#include "vroc/core/recording/atomic_output.h"
#include "vroc/core/recording/event_writer.h"
#include "vroc/core/recording/run_record.h"
#include "vroc/core/recording/trajectory_writer.h"
#include "vroc/core/scene_loader.h"

namespace vroc::recording {
namespace {
namespace fs = std::filesystem;
using test::splitCsv;
using test::splitLines;

// The independent reference for number formatting: printf's %.17g.
std::string printf17(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

BodyState stateOf(const Body& body) {
    return {body.pose, body.linear_velocity, body.angular_velocity};
}

TEST(TrajectoryWriter, HeaderThenOneRowPerVirtualBodyInSceneOrder) {
    const Scene scene = loadSceneFromString(test::kTwoBodyScene, "two_bodies.json");
    StringSink sink;
    TrajectoryWriter writer(sink, scene);
    std::vector<BodyState> states;
    for (const auto& body : scene.bodies) states.push_back(stateOf(body));
    writer.writeFrame(0.0, states);
    writer.writeFrame(0.01, states);
    writer.flush();

    const auto lines = splitLines(sink.text);
    ASSERT_EQ(lines.size(), 1u + 2u * 2u) << sink.text;
    EXPECT_EQ(lines[0], "t,body,x,y,z,qx,qy,qz,qw,vx,vy,vz,wx,wy,wz");
    EXPECT_EQ(splitCsv(lines[1])[1], "ball");
    EXPECT_EQ(splitCsv(lines[2])[1], "box");
    EXPECT_EQ(splitCsv(lines[3])[0], printf17(0.01));
    EXPECT_EQ(writer.rowsWritten(), 4u);
    // Every row has the 15 columns of the header.
    for (std::size_t i = 1; i < lines.size(); ++i) EXPECT_EQ(splitCsv(lines[i]).size(), 15u) << lines[i];
}

TEST(TrajectoryWriter, NumbersMatchPrintf17AndReadBackBitExact) {
    const Scene scene = loadSceneFromString(test::kTwoBodyScene, "two_bodies.json");
    // Awkward values: non-terminating binary fractions, extremes, a denormal, negative zero.
    const double values[] = {0.1, 1.0 / 3.0, -2.5e-300, 1.7976931348623157e308, 4.9e-324, -0.0, 123456789.125};
    std::vector<BodyState> states(scene.bodies.size());
    BodyState& ball = states[1];
    ball.pose.position = Vec3(values[0], values[1], values[2]);
    ball.pose.orientation = Quat(values[6], values[3], values[4], values[5]);   // w, x, y, z (not normalised)
    ball.linear_velocity = Vec3(values[5], values[4], values[0]);
    ball.angular_velocity = Vec3(values[1], values[2], values[3]);
    StringSink sink;
    TrajectoryWriter writer(sink, scene);
    writer.writeFrame(values[1], states);
    writer.flush();

    const auto row = splitCsv(splitLines(sink.text)[1]);
    const double expected[15] = {values[1], 0, values[0], values[1], values[2], values[3], values[4], values[5],
                                 values[6], values[5], values[4], values[0], values[1], values[2], values[3]};
    for (int c = 0; c < 15; ++c) {
        if (c == 1) continue;   // body name
        EXPECT_EQ(row[c], printf17(expected[c])) << "column " << c;
        const double back = std::strtod(row[c].c_str(), nullptr);
        EXPECT_EQ(std::memcmp(&back, &expected[c], sizeof back), 0) << "column " << c << ": " << row[c];
    }
}

TEST(TrajectoryWriter, NonFiniteStateIsARunError) {
    const Scene scene = loadSceneFromString(test::kTwoBodyScene, "two_bodies.json");
    std::vector<BodyState> states(scene.bodies.size());
    states[2].linear_velocity.y() = std::numeric_limits<double>::quiet_NaN();
    StringSink sink;
    TrajectoryWriter writer(sink, scene);
    EXPECT_THROW(writer.writeFrame(0.5, states), RunError);
    // Real bodies are not recorded, so their state may be anything.
    std::vector<BodyState> ok(scene.bodies.size());
    ok[0].pose.position.x() = std::numeric_limits<double>::infinity();
    EXPECT_NO_THROW(writer.writeFrame(0.5, ok));
}

TEST(EventWriter, RowsCountsAndPairs) {
    const Scene scene = loadSceneFromString(test::kTwoBodyScene, "two_bodies.json");
    StringSink sink;
    EventWriter writer(sink, scene);
    std::vector<CollisionEvent> events = {
        {0.25, 0, 1, Vec3(0.1, 0.2, 0.0), Vec3(0, 0, 1), 0.7},
        {0.5, 1, 2, Vec3(1.0, 1.0, 0.3), Vec3(0.6, 0.8, 0), 1.0 / 3.0},
        {0.75, 0, 1, Vec3(0.3, 0.2, 0.0), Vec3(0, 0, 1), 0.2},
    };
    writer.write(events);
    writer.flush();
    const auto lines = splitLines(sink.text);
    ASSERT_EQ(lines.size(), 4u);
    EXPECT_EQ(lines[0], "t,body_a,body_b,px,py,pz,nx,ny,nz,impulse");
    EXPECT_EQ(lines[1], "0.25,floor,ball,0.10000000000000001,0.20000000000000001,0,0,0,1,0.69999999999999996");
    EXPECT_EQ(splitCsv(lines[2])[1], "ball");
    EXPECT_EQ(splitCsv(lines[2])[2], "box");
    EXPECT_EQ(splitCsv(lines[2])[9], printf17(1.0 / 3.0));
    EXPECT_EQ(writer.count(), 3u);
    EXPECT_EQ(writer.pairCount(), 2u);
}

TEST(EventWriter, BadBodyIndexIsARunError) {
    const Scene scene = loadSceneFromString(test::kTwoBodyScene, "two_bodies.json");
    StringSink sink;
    EventWriter writer(sink, scene);
    const std::vector<CollisionEvent> out_of_range = {{0.1, 0, 3, Vec3::Zero(), Vec3(0, 0, 1), 1.0}};
    EXPECT_THROW(writer.write(out_of_range), RunError);
    const std::vector<CollisionEvent> self = {{0.1, 1, 1, Vec3::Zero(), Vec3(0, 0, 1), 1.0}};
    EXPECT_THROW(writer.write(self), RunError);
}

TEST(EventWriter, NamesWithCommasAreQuoted) {
    std::string text = test::kTwoBodyScene;
    text.replace(text.find("\"ball\", \"role\""), 6, "\"ba,l\\\"l\"");   // JSON "ba,l\"l"
    const Scene scene = loadSceneFromString(text, "quoted.json");
    StringSink sink;
    EventWriter writer(sink, scene);
    const std::vector<CollisionEvent> events = {{0.0, 0, 1, Vec3::Zero(), Vec3(0, 0, 1), 1.0}};
    writer.write(events);
    writer.flush();
    EXPECT_EQ(splitLines(sink.text)[1].substr(0, 18), "0,floor,\"ba,l\"\"l\",");
}

TEST(StepTimes, NearestRankPercentilesAgainstDefinition) {
    std::vector<double> v;
    for (int i = 100; i >= 1; --i) v.push_back(i);   // unsorted on purpose
    StepTimes s = summarizeStepTimes(v);
    EXPECT_EQ(s.p50, 50);
    EXPECT_EQ(s.p90, 90);
    EXPECT_EQ(s.p99, 99);
    EXPECT_EQ(s.max, 100);
    EXPECT_DOUBLE_EQ(s.mean, 50.5);
    // Ten samples: nearest rank ceil(p/100 * 10).
    s = summarizeStepTimes({10, 20, 30, 40, 50, 60, 70, 80, 90, 100});
    EXPECT_EQ(s.p50, 50);
    EXPECT_EQ(s.p90, 90);
    EXPECT_EQ(s.p99, 100);
    s = summarizeStepTimes({});
    EXPECT_EQ(s.p50, 0);
    EXPECT_EQ(s.max, 0);
}

TEST(AtomicFile, VisibleUnderFinalNameOnlyAfterCommit) {
    const fs::path dir = test::freshTempDir("atomic");
    {
        AtomicFile file(dir / "a.csv");
        file.write("hello\n");
        EXPECT_FALSE(fs::exists(dir / "a.csv"));
        EXPECT_TRUE(fs::exists(dir / "a.csv.tmp"));
        file.commit();
    }
    EXPECT_EQ(test::readText((dir / "a.csv").string()), "hello\n");
    EXPECT_FALSE(fs::exists(dir / "a.csv.tmp"));
    {
        AtomicFile abandoned(dir / "b.csv");
        abandoned.write("partial");
    }
    EXPECT_FALSE(fs::exists(dir / "b.csv"));
    EXPECT_FALSE(fs::exists(dir / "b.csv.tmp"));
    fs::remove_all(dir);
}

TEST(AtomicFile, UnwritablePlaceIsAnInputError) {
    EXPECT_THROW(AtomicFile("/proc/vroc-no-such-dir/x.csv"), InputError);
}

TEST(PrepareOutputDirectory, CreatesNestedAndRemovesAnEarlierRunJson) {
    const fs::path dir = test::freshTempDir("prepare");
    EXPECT_TRUE(prepareOutputDirectory(dir / "a" / "b"));
    EXPECT_TRUE(fs::is_directory(dir / "a" / "b"));
    test::writeFile(dir / "a" / "b" / "run.json", "{}");
    EXPECT_FALSE(prepareOutputDirectory(dir / "a" / "b"));
    EXPECT_FALSE(fs::exists(dir / "a" / "b" / "run.json"));
    EXPECT_TRUE(fs::is_empty(dir / "a" / "b"));   // the write probe is gone too
    fs::remove_all(dir);
}

TEST(PrepareOutputDirectory, UnwritableOrNotADirectoryIsAnInputError) {
    const fs::path dir = test::freshTempDir("prepare-bad");
    test::writeFile(dir / "file", "x");
    EXPECT_THROW(prepareOutputDirectory(dir / "file"), InputError);
    EXPECT_THROW(prepareOutputDirectory(dir / "file" / "sub"), InputError);
    EXPECT_THROW(prepareOutputDirectory("/proc/vroc-out"), InputError);
    fs::remove_all(dir);
}

TEST(RunRecordJson, ParsesBackWithEveryField) {
    RunRecord r;
    r.scene_name = "s";
    r.scene_sha256 = std::string(64, 'a');
    r.backend_name = "b";
    r.settings = {{"b.k", "3"}};
    r.frame_dt = 1.0 / 60.0;
    r.duration = 5;
    r.steps = 300;
    r.step_wall_us = {1, 2, 3, 1.5, 4};
    r.collision_count = 7;
    r.pair_count = 2;
    r.warnings = {{"walk_not_converged", 5}};
    r.statistics = {{"pairs", 3.5}, {"bad", std::numeric_limits<double>::quiet_NaN()}};
    r.state_hash = "0123456789abcdef";
    r.build = buildInfo();
    const auto j = nlohmann::json::parse(toJson(r));
    EXPECT_EQ(j["format"], "vroc-run/1");
    EXPECT_EQ(j["scene"]["name"], "s");
    EXPECT_EQ(j["settings"]["b.k"], "3");
    EXPECT_EQ(j["frame_dt"].get<double>(), 1.0 / 60.0);   // round-trip exact
    EXPECT_EQ(j["steps"], 300);
    EXPECT_EQ(j["step_wall_time_us"]["p99"], 3.0);
    EXPECT_EQ(j["warnings"]["walk_not_converged"], 5);
    EXPECT_EQ(j["statistics"]["pairs"], 3.5);
    EXPECT_TRUE(j["statistics"]["bad"].is_null());
    EXPECT_EQ(j["state_hash"], "0123456789abcdef");
    EXPECT_EQ(j["build"]["compiler"], buildInfo().compiler);
    EXPECT_FALSE(buildInfo().version.empty());
}

TEST(UtcNow, IsIso8601) {
    const std::string t = utcNowIso8601();
    ASSERT_EQ(t.size(), 20u) << t;
    EXPECT_EQ(t[4], '-');
    EXPECT_EQ(t[10], 'T');
    EXPECT_EQ(t[19], 'Z');
}

}  // namespace
}  // namespace vroc::recording
