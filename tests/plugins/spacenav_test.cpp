// SPDX-License-Identifier: MIT
// The spacenav plugin with the real libspnav against a test spacenavd (spacenavd_test_daemon.h).
// The host clock is frozen while each event travels, so every event carries a known host time and
// the integrated pose has a closed form, recomputed here from the counts sent.
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <thread>
#include <unistd.h>

#include <gtest/gtest.h>

#include "plugin_test_host.h"
#include "spacenavd_test_daemon.h"
#include "vroc/core/errors.h"
#include "wait_for.h"

namespace vroc::plugins::test {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int64_t kSecond = 1'000'000'000;

std::string socketPath(const std::string& tag) {
    return ::testing::TempDir() + "vroc-spnav-" + std::to_string(getpid()) + "-" + tag + ".sock";
}

using vroc::test::waitFor;  // tests/support/wait_for.h

// Segments of constant motion in VROC's frame, written out by hand from the counts sent (full
// scale 350, max_speed 0.5 m/s, max_rate 90 deg/s; spacenavd (x, y, z) -> VROC (z, -x, y), the
// same for rotations).
struct Segment {
    double start;     // [s]
    Vec3 velocity;    // [m/s] base frame
    Vec3 body_rate;   // [rad/s] sensor frame
};

struct Expected {
    Vec3 position;
    Quat orientation;
};

Expected integrate(const std::vector<Segment>& segments, const Vec3& origin, double t) {
    Expected e{origin, Quat::Identity()};
    for (size_t i = 0; i < segments.size(); ++i) {
        const double begin = segments[i].start;
        const double end = i + 1 < segments.size() ? segments[i + 1].start : 1e30;
        if (t <= begin) break;
        const double dt = std::min(t, end) - begin;
        e.position += segments[i].velocity * dt;
        const double rate = segments[i].body_rate.norm();
        if (rate > 0) e.orientation = e.orientation * Quat(Eigen::AngleAxisd(rate * dt, segments[i].body_rate / rate));
    }
    return e;
}

class SpacenavPlugin : public ::testing::Test {
protected:
    std::atomic<int64_t> clock_{kSecond};
    std::shared_ptr<LogCapture> capture_ = std::make_shared<LogCapture>();
    std::unique_ptr<PluginHost> host_ = makeTestHost(capture_, [this] { return clock_.load(); });
};

TEST_F(SpacenavPlugin, ReportsAxesButtonsAndTheIntegratedPoseOfTheEventsSent) {
    SpacenavdTestDaemon daemon(socketPath("v1"), 1);
    auto device = host_->open("spacenav", "socket=" + daemon.path() +
                                              ",full_scale=350,max_speed=0.5,max_rate_deg=90,x=0,y=0,z=1");
    // What libspnav told the daemon while the plugin opened the device.
    EXPECT_EQ(daemon.firstMessages(), std::vector<uint32_t>{0x7faa5501u});  // protocol request, version 1
    EXPECT_EQ(daemon.negotiatedProtocol(), 1);
    EXPECT_EQ(daemon.clientName(), "vroc");
    EXPECT_EQ(daemon.evmask(), SpacenavdTestDaemon::kEvmaskMotion | SpacenavdTestDaemon::kEvmaskButton);
    EXPECT_TRUE(daemon.otherRequests().empty());
    EXPECT_EQ(capture_->count("connected to spacenavd at " + daemon.path() + " (protocol 1)"), 1u);

    uint64_t events = 0;
    auto at = [&](double seconds, auto&& send, int count) {
        clock_ = static_cast<int64_t>(std::llround(seconds * 1e9));
        send();
        events += count;
        ASSERT_TRUE(waitFor([&] { return device->pose(0, clock_).sample.sequence == events; })) << "t=" << seconds;
    };
    at(2.0, [&] { daemon.sendMotion({0, 0, 175, 0, 0, 0}); }, 1);   // half forward
    at(3.0, [&] { daemon.sendMotion({-700, 0, 0, 0, 0, 0}); daemon.sendButton(0, true); }, 2);  // full left (clamped)
    at(4.0, [&] { daemon.sendMotion({0, 0, 0, 0, 175, 0}); }, 1);   // half twist about up
    at(5.0, [&] { daemon.sendMotion({0, 350, 0, 350, 0, 0}); }, 1); // up, and tilt
    at(6.0, [&] { daemon.sendMotion({0, 0, 0, 0, 0, 0}); daemon.sendButton(0, false); daemon.sendButton(3, true); }, 3);
    at(7.0, [&] { daemon.sendMotion({0, 0, -350, 0, 0, -350}); }, 1);  // back, and roll
    at(8.0, [&] { daemon.disconnect(); }, 1);  // the daemon goes away: the plugin releases everything
    ASSERT_TRUE(waitFor([&] { return !device->pose(0, 9 * kSecond).sample.has(VROC_POSE_POSITION_TRACKED); }));
    // The reader thread logs the close just after it marks the pose untracked, outside the lock the
    // pose is read under: wait for the line (bounded) before counting it exactly once below.
    ASSERT_TRUE(waitFor([&] { return capture_->count("closed the connection") > 0; }))
        << "no 'closed the connection' logged within 10 s of the pose going untracked";

    const double r = kPi / 2;  // [rad/s] at full deflection
    const std::vector<Segment> segments = {
        {2, {0.25, 0, 0}, {0, 0, 0}}, {3, {0, 0.5, 0}, {0, 0, 0}},  {4, {0, 0, 0}, {0, 0, r / 2}},
        {5, {0, 0, 0.5}, {0, -r, 0}}, {6, {0, 0, 0}, {0, 0, 0}},    {7, {-0.5, 0, 0}, {-r, 0, 0}},
        {8, {0, 0, 0}, {0, 0, 0}}};
    const Vec3 origin(0, 0, 1);
    for (double t = 0.5; t <= 9.5; t += 0.25) {
        const int64_t ns = static_cast<int64_t>(std::llround(t * 1e9));
        const PoseResult pose = device->pose(0, ns);
        ASSERT_TRUE(pose.ok()) << pose.message;
        const Expected e = integrate(segments, origin, t);
        EXPECT_LT((pose.sample.pose.position - e.position).norm(), 1e-12) << "t=" << t;
        EXPECT_LT(angleBetween(pose.sample.pose.orientation, e.orientation), 1e-9) << "t=" << t;
        EXPECT_EQ(pose.sample.time_ns, ns);
        EXPECT_EQ(pose.sample.has(VROC_POSE_POSITION_TRACKED), t < 8) << "t=" << t;
    }
    // Two closed forms by hand: at 6 s moved (0.25, 0.5, 0.5), yawed 45 deg then pitched -90 deg.
    const PoseResult six = device->pose(0, 6 * kSecond);
    EXPECT_LT((six.sample.pose.position - Vec3(0.25, 0.5, 1.5)).norm(), 1e-12);
    const Quat q6 = Quat(Eigen::AngleAxisd(kPi / 4, Vec3::UnitZ())) * Quat(Eigen::AngleAxisd(-kPi / 2, Vec3::UnitY()));
    EXPECT_LT(angleBetween(six.sample.pose.orientation, q6), 1e-9);
    // Velocities while tilting: base-frame rate = orientation x body rate.
    const PoseResult mid = device->pose(0, 5 * kSecond + kSecond / 2);
    EXPECT_LT((mid.sample.linear_velocity - Vec3(0, 0, 0.5)).norm(), 1e-12);
    EXPECT_LT((mid.sample.angular_velocity - mid.sample.pose.orientation * Vec3(0, -r, 0)).norm(), 1e-12);

    // Controls: the held deflections in VROC's axes and the buttons, stamped with the event time.
    const struct {
        double t;
        std::array<double, 6> axes;
        uint64_t buttons;
    } controls[] = {{1.5, {0, 0, 0, 0, 0, 0}, 0},   {2.5, {0.5, 0, 0, 0, 0, 0}, 0}, {3.5, {0, 1, 0, 0, 0, 0}, 1},
                    {4.5, {0, 0, 0, 0, 0, 0.5}, 1}, {5.5, {0, 0, 1, 0, -1, 0}, 1},  {6.5, {0, 0, 0, 0, 0, 0}, 8},
                    {7.5, {-1, 0, 0, -1, 0, 0}, 8}, {8.5, {0, 0, 0, 0, 0, 0}, 0}};
    for (const auto& c : controls) {
        const ControlResult result = device->controls(static_cast<int64_t>(std::llround(c.t * 1e9)));
        ASSERT_TRUE(result.ok()) << result.message;
        ASSERT_EQ(result.state.axes.size(), 6u);
        for (int i = 0; i < 6; ++i) EXPECT_EQ(result.state.axes[i], c.axes[i]) << "t=" << c.t << " axis " << i;
        EXPECT_EQ(result.state.buttons, c.buttons) << "t=" << c.t;
        EXPECT_EQ(result.state.time_ns, static_cast<int64_t>(std::floor(c.t)) * kSecond) << "t=" << c.t;
    }
    EXPECT_EQ(capture_->count("closed the connection"), 1u);

    // The same session as a spacemouse-sim script: the two 3D mice integrate alike.
    auto sim = host_->open("spacemouse-sim",
                           "start=2,x=0,y=0,z=1,max_speed=0.5,max_rate_deg=90,script=1:0.5:0:0:0:0:0:0/"
                           "1:0:1:0:0:0:0:1/1:0:0:0:0:0:0.5:1/1:0:0:1:0:-1:0:1/1:0:0:0:0:0:0:8/1:-1:0:0:-1:0:0:8");
    for (double t = 1.0; t <= 9.5; t += 0.5) {
        const int64_t ns = static_cast<int64_t>(std::llround(t * 1e9));
        const PoseResult a = device->pose(0, ns), b = sim->pose(0, ns);
        EXPECT_LT((a.sample.pose.position - b.sample.pose.position).norm(), 1e-12) << "t=" << t;
        EXPECT_LT(angleBetween(a.sample.pose.orientation, b.sample.pose.orientation), 1e-12) << "t=" << t;
        EXPECT_EQ(device->controls(ns).state.buttons, sim->controls(ns).state.buttons) << "t=" << t;
    }
}

TEST_F(SpacenavPlugin, OldDaemonWithoutProtocolOneStillDeliversEvents) {
    SpacenavdTestDaemon daemon(socketPath("v0"), 0);
    auto device = host_->open("spacenav", "socket=" + daemon.path());
    // libspnav asked for protocol 1, heard nothing for 300 ms and sent the v0 sensitivity 1.0.
    ASSERT_TRUE(waitFor([&] { return daemon.firstMessages().size() == 2; }));
    EXPECT_EQ(daemon.firstMessages()[0], 0x7faa5501u);
    EXPECT_EQ(daemon.firstMessages()[1], std::bit_cast<uint32_t>(1.0f));
    EXPECT_EQ(daemon.clientName(), "");  // protocol-1 requests are not sent to an old daemon
    EXPECT_EQ(capture_->count("(protocol 0)"), 1u);
    clock_ = 2 * kSecond;
    daemon.sendMotion({0, 0, 0, 0, -350, 0});
    daemon.sendButton(1, true);
    ASSERT_TRUE(waitFor([&] { return device->pose(0, clock_).sample.sequence == 2; }));
    const ControlResult c = device->controls(3 * kSecond);
    ASSERT_TRUE(c.ok());
    EXPECT_EQ(c.state.axes[5], -1.0);  // spacenavd ry -> VROC rz
    EXPECT_EQ(c.state.buttons, 2u);
    const PoseResult p = device->pose(0, 3 * kSecond);  // one second of full yaw the other way
    EXPECT_LT(angleBetween(p.sample.pose.orientation, Quat(Eigen::AngleAxisd(-kPi / 2, Vec3::UnitZ()))), 1e-12);
}

TEST_F(SpacenavPlugin, MissingDaemonSecondDeviceAndBadOptionsAreClearErrors) {
    const std::string nowhere = socketPath("nobody");
    try {
        host_->open("spacenav", "socket=" + nowhere);
        FAIL() << "opened without a daemon";
    } catch (const InputError& e) {
        // Either nothing answered anywhere, or libspnav fell back to a real daemon and the plugin
        // refused it: both name the socket asked for.
        const std::string what = e.what();
        EXPECT_TRUE(what.find("cannot connect to spacenavd (tried " + nowhere + ")") != std::string::npos ||
                    what.find("no spacenavd at " + nowhere) != std::string::npos) << what;
    }
    SpacenavdTestDaemon daemon(socketPath("one"), 1);
    auto first = host_->open("spacenav", "socket=" + daemon.path());
    try {
        host_->open("spacenav", "socket=" + daemon.path());
        FAIL() << "opened twice";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("libspnav allows one connection per process"), std::string::npos)
            << e.what();
    }
    first.reset();  // closing frees libspnav for the next device
    try {
        host_->open("spacenav", "socket=" + daemon.path() + ",full_scale=0");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("spacenav: option full_scale='0': expected a number in [1"),
                  std::string::npos) << e.what();
    }
    EXPECT_THROW(host_->open("spacenav", "socket=" + daemon.path() + ",bogus=1"), InputError);
}

}  // namespace
}  // namespace vroc::plugins::test
