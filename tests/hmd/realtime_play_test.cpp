// SPDX-License-Identifier: MIT
// `vroc play --realtime` with a live head tracker: a thread sends datagrams exactly as opentrack's
// "UDP over network" output does (tests/plugins/opentrack_sender.h, 250 Hz) to the `udp` plugin
// while the loop runs paced to the wall clock. Each frame's head sample must be one of the poses
// sent (mapped to VROC's frame by the documented opentrack convention) and have arrived after it
// was sent; the latency figures must be present and plausible; missed frames are counted, not
// required to be zero (2 loaded cores). Also the pacer's bookkeeping and the latency summary.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "../plugins/opentrack_sender.h"
#include "test_backends.h"
#include "vroc/play/frame_pacer.h"
#include "vroc/play/play_loop.h"

namespace vroc::play {
namespace {

std::int64_t steadyNs() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

// A port the kernel considers free right now (bound to 0, read back, released).
int freeLoopbackPort() {
    const int fd = socket(AF_INET, SOCK_DGRAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address);
    socklen_t length = sizeof address;
    getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length);
    close(fd);
    return ntohs(address.sin_port);
}

/// opentrack's pose (TX, TY, TZ [cm], yaw, pitch, roll [deg]) in VROC's base frame, as
/// docs/plugin-abi.md states the convention: position (-TZ, -TX, TY) / 100, Rz(yaw) Ry(pitch) Rx(roll).
Pose fromOpentrack(const plugins::test::OpentrackPose& v) {
    constexpr double deg = M_PI / 180;
    const Quat q = Quat(Eigen::AngleAxisd(v[3] * deg, Vec3::UnitZ())) * Quat(Eigen::AngleAxisd(v[4] * deg, Vec3::UnitY())) *
                   Quat(Eigen::AngleAxisd(v[5] * deg, Vec3::UnitX()));
    return {Vec3(-v[2], -v[0], v[1]) / 100.0, q};
}

TEST(RealtimePlay, OpentrackHeadArrivesAndLatencyIsMeasured) {
    test::registerBackendsOnce();
    const int port = freeLoopbackPort();
    // A head nodding and turning slowly near (0.3, -0.1, 0.05) m.
    auto pose_at = [](double t) -> plugins::test::OpentrackPose {
        return {10 * std::sin(M_PI * t), 5.0, -30 + 5 * std::cos(M_PI * t), 20 * std::sin(M_PI * t),
                5 * std::sin(0.6 * M_PI * t), 0.0};
    };
    struct Sent {
        std::int64_t ns;
        Pose pose;
    };
    std::mutex mutex;
    std::vector<Sent> sent;
    std::atomic<bool> stop{false};
    int datagrams = 0;
    std::thread sender_thread([&] {
        plugins::test::OpentrackSender sender(port);
        datagrams = sender.stream(
            [&](double t) {
                const plugins::test::OpentrackPose p = pose_at(t);
                std::lock_guard lock(mutex);
                sent.push_back({steadyNs(), fromOpentrack(p)});   // stamped just before it is sent
                return p;
            },
            10.0, &stop);
    });

    PlayOptions o;
    o.scene_path = std::string(VROC_SOURCE_DIR) + "/scenes/staircase.json";
    o.backend = "bullet";
    o.head_spec = "udp:port=" + std::to_string(port);
    o.frames = 90;   // 1.5 s at 60 frames/s
    o.eye_width = 64;
    o.eye_height = 48;
    o.realtime = true;
    const std::int64_t wall_start = steadyNs();
    PlayReport r;
    try {
        r = runPlay(o);
    } catch (...) {
        stop = true;
        sender_thread.join();
        throw;
    }
    const double wall_s = static_cast<double>(steadyNs() - wall_start) * 1e-9;
    stop = true;
    sender_thread.join();

    // Paced: 90 frames of 1/60 s cannot finish before 1.5 s of wall time.
    EXPECT_GE(wall_s, 1.5 - 1e-3);
    EXPECT_TRUE(r.realtime);
    EXPECT_GE(r.frames_missed, 0);
    EXPECT_LE(r.frames_missed, r.frames);

    // Every frame's head sample is a pose that was sent, and arrived after it was sent.
    ASSERT_EQ(r.head_trace.size(), 90u);
    int valid = 0, matched = 0, distinct = 0;
    std::uint64_t last_sequence = 0;
    double worst_transit_ms = 0;
    for (const DeviceFrame& f : r.head_trace) {
        if (!f.valid) continue;
        ++valid;
        if (f.sequence != last_sequence) ++distinct;
        last_sequence = f.sequence;
        std::lock_guard lock(mutex);
        for (auto it = sent.rbegin(); it != sent.rend(); ++it) {
            if (it->ns > f.sample_time_ns) continue;   // sent after it arrived: not this one
            if ((it->pose.position - f.pose.position).norm() < 1e-12 &&
                it->pose.orientation.angularDistance(f.pose.orientation) < 1e-9) {
                ++matched;
                worst_transit_ms = std::max(worst_transit_ms, static_cast<double>(f.sample_time_ns - it->ns) * 1e-6);
                break;
            }
        }
    }
    const LatencySummary& head = r.latency_ms.at("head");
    std::printf("%d datagrams sent; %d of 90 frames had a head sample (%d distinct), %d matched a sent pose "
                "(worst send -> arrival %.2f ms); head latency sample -> frame done: mean %.2f ms, p50 %.2f, "
                "p95 %.2f, max %.2f; %d frames missed their deadline (worst %.2f ms late); %.3f s wall\n",
                datagrams, valid, distinct, matched, worst_transit_ms, head.mean, head.p50, head.p95, head.max,
                r.frames_missed, r.worst_lateness_ms, wall_s);
    EXPECT_GE(valid, 80);            // datagrams flow from before the first frame
    EXPECT_EQ(matched, valid);
    EXPECT_GE(distinct, valid / 2);  // 250 Hz in, 60 Hz out: nearly every frame sees a new pose
    // Latency: one per frame with a sample, positive, and well under a few frames at the median.
    EXPECT_EQ(head.count, valid);
    EXPECT_GT(head.p50, 0.0);
    EXPECT_GT(head.mean, 0.0);
    EXPECT_LT(head.p50, 3 * 1000.0 / 60.0);
    EXPECT_LE(head.p50, head.p95);
    EXPECT_LE(head.p95, head.max);
}

TEST(RealtimePlay, PacerDeadlinesAndMisses) {
    const std::int64_t zero = steadyNs();
    FramePacer pacer(0.01, zero);
    EXPECT_EQ(pacer.deadline(0), zero + 10'000'000);
    EXPECT_EQ(pacer.deadline(99), zero + 1'000'000'000);
    // Done late: counted, no wait.
    EXPECT_TRUE(pacer.finishFrame(0, zero + 12'500'000));
    EXPECT_EQ(pacer.missed(), 1);
    EXPECT_DOUBLE_EQ(pacer.worstLateness(), 2.5);
    // Done early: waits until the deadline (frame 5 is due 60 ms after zero).
    EXPECT_FALSE(pacer.finishFrame(5, steadyNs()));
    EXPECT_GE(steadyNs(), zero + 60'000'000);
    EXPECT_EQ(pacer.missed(), 1);
}

TEST(RealtimePlay, LatencySummaryIsNearestRank) {
    std::vector<double> ms;
    for (int i = 20; i >= 1; --i) ms.push_back(i);   // 1 .. 20, unsorted
    const LatencySummary s = summariseLatencies(ms);
    EXPECT_EQ(s.count, 20);
    EXPECT_DOUBLE_EQ(s.mean, 10.5);
    EXPECT_DOUBLE_EQ(s.p50, 10.0);   // ceil(0.50 * 20) = 10th value
    EXPECT_DOUBLE_EQ(s.p95, 19.0);   // ceil(0.95 * 20) = 19th value
    EXPECT_DOUBLE_EQ(s.max, 20.0);
    EXPECT_EQ(summariseLatencies({}).count, 0);
}

}  // namespace
}  // namespace vroc::play
