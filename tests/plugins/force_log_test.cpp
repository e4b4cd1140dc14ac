// SPDX-License-Identifier: MIT
// The force-log decorator: poses and controls pass through untouched, every force is logged
// exactly, and the log looks complete only once it is.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "plugin_test_host.h"
#include "vroc/core/errors.h"

namespace vroc::plugins::test {
namespace {

namespace fs = std::filesystem;

std::string tempPath(const std::string& name) {
    return ::testing::TempDir() + "vroc-force-log-" + std::to_string(getpid()) + "-" + name;
}

struct ForceRow {
    int64_t time_ns;
    uint32_t sensor;
    double values[6];  // fx fy fz tx ty tz
};

// Parses the log independently of the plugin's writer; fails the test on a malformed line.
std::vector<ForceRow> readLog(const std::string& path) {
    std::ifstream in(path);
    std::string line;
    EXPECT_TRUE(std::getline(in, line)) << path;
    EXPECT_EQ(line, "time_ns,sensor,fx,fy,fz,tx,ty,tz");
    std::vector<ForceRow> rows;
    while (std::getline(in, line)) {
        ForceRow row{};
        std::istringstream cells(line);
        std::string cell;
        std::vector<std::string> parts;
        while (std::getline(cells, cell, ',')) parts.push_back(cell);
        EXPECT_EQ(parts.size(), 8u) << line;
        if (parts.size() != 8) continue;
        row.time_ns = std::stoll(parts[0]);
        row.sensor = static_cast<uint32_t>(std::stoul(parts[1]));
        for (int i = 0; i < 6; ++i) row.values[i] = std::strtod(parts[2 + i].c_str(), nullptr);
        rows.push_back(row);
    }
    return rows;
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(ForceLogPlugin, PosesAndControlsPassThroughUnchanged) {
    auto host = makeTestHost();
    const std::string out = tempPath("pass.csv");
    auto logged = host->open("force-log", "out=" + out + ",inner=analytic,inner.motion=throw,inner.radius=0.6");
    auto direct = host->open("analytic", "motion=throw,radius=0.6");
    EXPECT_TRUE(logged->acceptsForce());
    for (int64_t t = 0; t < 2'000'000'000; t += 37'000'000) {
        const PoseResult a = logged->pose(0, t), b = direct->pose(0, t);
        ASSERT_TRUE(a.ok() && b.ok());
        EXPECT_EQ(a.sample.time_ns, b.sample.time_ns);
        EXPECT_EQ(a.sample.flags, b.sample.flags);
        EXPECT_EQ(a.sample.sequence, b.sample.sequence);
        EXPECT_EQ(a.sample.pose.position, b.sample.pose.position);
        EXPECT_EQ(a.sample.pose.orientation.coeffs(), b.sample.pose.orientation.coeffs());
        EXPECT_EQ(a.sample.linear_velocity, b.sample.linear_velocity);
        EXPECT_EQ(a.sample.angular_velocity, b.sample.angular_velocity);
        EXPECT_EQ(logged->controls(t).state.buttons, direct->controls(t).state.buttons);
    }
    // The inner device's errors come back with their text.
    const PoseResult bad = logged->pose(1, 0);
    EXPECT_EQ(bad.status, SampleStatus::Failed);
    EXPECT_NE(bad.message.find("force-log: inner device: analytic: only sensor 0 exists"), std::string::npos)
        << bad.message;
    logged.reset();
    fs::remove(out);
}

TEST(ForceLogPlugin, LogIsExactFlushedRowByRowAndCompleteOnlyAfterClose) {
    auto host = makeTestHost();
    const std::string out = tempPath("exact.csv"), partial = out + ".partial";
    {
        std::ofstream stale(out);  // a log from an earlier run must not survive as this run's
        stale << "time_ns,sensor,fx,fy,fz,tx,ty,tz\n1,0,9,9,9,9,9,9\n";
    }
    const double awkward[][6] = {{0.1, 1.0 / 3, -0.0, 1e-300, 6.02214076e23, -2.5},
                                 {std::nextafter(1.0, 2.0), -1e-17, 123456.789, 0, 5e-324, -7}};
    auto device = host->open("force-log", "out=" + out + ",inner=analytic");
    EXPECT_FALSE(fs::exists(out));
    for (int i = 0; i < 2; ++i) {
        const double* v = awkward[i];
        ASSERT_TRUE(device->sendForce(i, -5 + 1'000'000'007LL * i, Vec3(v[0], v[1], v[2]), Vec3(v[3], v[4], v[5])));
        // Flushed: a reader sees the row at once, still under the .partial name.
        EXPECT_EQ(readLog(partial).size(), static_cast<size_t>(i + 1));
        EXPECT_FALSE(fs::exists(out));
    }
    device.reset();  // destroy: close and rename
    EXPECT_FALSE(fs::exists(partial));
    const std::vector<ForceRow> rows = readLog(out);
    ASSERT_EQ(rows.size(), 2u);
    for (int i = 0; i < 2; ++i) {
        EXPECT_EQ(rows[i].time_ns, -5 + 1'000'000'007LL * i);
        EXPECT_EQ(rows[i].sensor, static_cast<uint32_t>(i));
        for (int k = 0; k < 6; ++k)
            EXPECT_TRUE(sameBits(rows[i].values[k], awkward[i][k])) << "row " << i << " value " << k << ": "
                                                                     << rows[i].values[k] << " vs " << awkward[i][k];
    }
    fs::remove(out);
}

// A held box pushed into a wall: the hand moves along a line through the wall plane and the
// coupling answers with a spring force, stiffness x penetration of the hand. The log must hold
// exactly that force for every frame, recomputed here from the closed-form line.
TEST(ForceLogPlugin, HandPushedIntoAWallLogsStiffnessTimesPenetration) {
    auto host = makeTestHost();
    const std::string out = tempPath("wall.csv");
    constexpr double kStart = 0.2, kSpeed = 0.5, kWall = 0.4, kStiffness = 2000.0;  // m, m/s, m, N/m
    auto hand = host->open("force-log", "out=" + out +
                                            ",inner=analytic,inner.motion=line,inner.x=0.2,inner.y=0,inner.z=1,"
                                            "inner.vx=0.5,inner.press_at=0");
    const int frames = 100;
    for (int i = 0; i < frames; ++i) {
        const int64_t t = i * 10'000'000LL;  // 100 Hz
        const PoseResult r = hand->pose(0, t);
        ASSERT_TRUE(r.ok());
        EXPECT_EQ(hand->controls(t).state.buttons & 1u, 1u);  // held throughout
        const double penetration = std::max(0.0, r.sample.pose.position.x() - kWall);
        ASSERT_TRUE(hand->sendForce(0, t, Vec3(-kStiffness * penetration, 0, 0), Vec3::Zero()));
    }
    hand.reset();
    const std::vector<ForceRow> rows = readLog(out);
    ASSERT_EQ(rows.size(), static_cast<size_t>(frames));
    double peak = 0;
    for (int i = 0; i < frames; ++i) {
        const double t = i * 0.01;
        const double expected = -kStiffness * std::max(0.0, kStart + kSpeed * t - kWall);
        EXPECT_EQ(rows[i].time_ns, i * 10'000'000LL);
        EXPECT_NEAR(rows[i].values[0], expected, 1e-9) << "t=" << t;
        EXPECT_EQ(rows[i].values[1], 0.0);
        peak = std::min(peak, rows[i].values[0]);
    }
    // Contact from t = 0.4 s; at t = 0.99 s the hand is 0.295 m deep: 590 N.
    EXPECT_NEAR(rows[40].values[0], 0.0, 1e-9);  // touching
    EXPECT_LT(rows[41].values[0], 0.0);
    EXPECT_NEAR(peak, -590.0, 1e-9);
    fs::remove(out);
}

TEST(ForceLogPlugin, BadOptionsAreOneLineErrorsAndLeaveNoFile) {
    auto host = makeTestHost();
    const std::string out = tempPath("bad.csv");
    const std::pair<std::string, std::string> cases[] = {
        {"inner=analytic", "force-log: option out=PATH is required"},
        {"out=" + out, "force-log: option inner=PLUGIN is required"},
        {"out=" + out + ",inner=analytic,bogus=1", "force-log: unknown option 'bogus'"},
        {"out=" + out + ",inner=force-log", "inner=force-log would wrap itself"},
        {"out=" + out + ",inner=no-such-plugin", "force-log: cannot load inner plugin 'no-such-plugin'"},
        {"out=" + out + ",inner=analytic,inner.motion=zigzag",
         "force-log: inner analytic: analytic: option motion='zigzag'"},
        {"out=/nonexistent-dir/forces.csv,inner=analytic", "cannot create /nonexistent-dir/forces.csv.partial"},
    };
    for (const auto& [options, expected] : cases) {
        try {
            host->open("force-log", options);
            FAIL() << options;
        } catch (const InputError& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find(expected), std::string::npos) << what;
            EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        }
        EXPECT_FALSE(fs::exists(out)) << options;
        EXPECT_FALSE(fs::exists(out + ".partial")) << options;
    }
}

}  // namespace
}  // namespace vroc::plugins::test
