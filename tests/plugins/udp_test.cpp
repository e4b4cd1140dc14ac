// SPDX-License-Identifier: MIT
// The udp plugin on loopback: a sender socket writes opentrack datagrams to an ephemeral port.
#include <arpa/inet.h>
#include <array>
#include <bit>
#include <chrono>
#include <cmath>
#include <limits>
#include <netinet/in.h>
#include <sys/socket.h>
#include <thread>
#include <unistd.h>

#include <gtest/gtest.h>

#include "opentrack_sender.h"
#include "plugin_test_host.h"
#include "wait_for.h"

namespace vroc::plugins::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

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

class Sender {
public:
    explicit Sender(int port) : fd_(socket(AF_INET, SOCK_DGRAM, 0)) {
        to_.sin_family = AF_INET;
        to_.sin_port = htons(static_cast<uint16_t>(port));
        to_.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    }
    ~Sender() { close(fd_); }
    void send(const void* data, size_t size) {
        ASSERT_EQ(sendto(fd_, data, size, 0, reinterpret_cast<sockaddr*>(&to_), sizeof to_), static_cast<ssize_t>(size));
    }
    void send(const std::array<double, 6>& values) { send(values.data(), sizeof values); }

private:
    int fd_;
    sockaddr_in to_{};
};

using vroc::test::waitFor;  // tests/support/wait_for.h

TEST(UdpPlugin, ReceivesOpentrackDatagramsAndDropsBadOnes) {
    auto capture = std::make_shared<LogCapture>();
    auto host = makeTestHost(capture);
    const int port = freeLoopbackPort();
    auto device = host->open("udp", "port=" + std::to_string(port) + ",stale=60");
    EXPECT_EQ(device->pose(0, host->nowNs()).status, SampleStatus::NoData);

    Sender sender(port);
    const int64_t before = host->nowNs();
    sender.send({10.0, 20.0, -30.0, 90.0, 0.0, 0.0});  // cm, cm, cm, yaw, pitch, roll [deg]
    ASSERT_TRUE(waitFor([&] { return device->pose(0, host->nowNs()).ok(); }));
    PoseResult r = device->pose(0, host->nowNs());
    EXPECT_EQ(r.sample.sequence, 1u);
    EXPECT_GE(r.sample.time_ns, before);
    // position = (-TZ, -TX, TY) / 100; yaw about +z.
    EXPECT_LT((r.sample.pose.position - Vec3(0.30, -0.10, 0.20)).norm(), 1e-12);
    EXPECT_LT(angleBetween(r.sample.pose.orientation, Quat(Eigen::AngleAxisd(kPi / 2, Vec3::UnitZ()))), 1e-9);
    EXPECT_TRUE(r.sample.has(VROC_POSE_ORIENTATION_TRACKED));

    // A NaN datagram and a short one: both dropped, the pose stays the first one.
    sender.send({std::numeric_limits<double>::quiet_NaN(), 0, 0, 0, 0, 0});
    const double short_datagram[5] = {1, 2, 3, 4, 5};
    sender.send(short_datagram, sizeof short_datagram);
    ASSERT_TRUE(waitFor([&] { return capture->count("dropped") == 2; }));
    EXPECT_EQ(capture->count("dropped datagram with a non-finite value"), 1u);
    EXPECT_EQ(capture->count("dropped datagram of 40 bytes, expected 48"), 1u);
    r = device->pose(0, host->nowNs());
    EXPECT_EQ(r.sample.sequence, 1u);
    EXPECT_LT((r.sample.pose.position - Vec3(0.30, -0.10, 0.20)).norm(), 1e-12);

    // Pitch about the left (+y) axis, roll about forward (+x): Rz(yaw) Ry(pitch) Rx(roll).
    sender.send({0, 0, 0, 30.0, -20.0, 10.0});
    ASSERT_TRUE(waitFor([&] { return device->pose(0, host->nowNs()).sample.sequence == 2; }));
    r = device->pose(0, host->nowNs());
    const Quat expected = Quat(Eigen::AngleAxisd(kPi / 6, Vec3::UnitZ())) *
                          Quat(Eigen::AngleAxisd(-kPi / 9, Vec3::UnitY())) *
                          Quat(Eigen::AngleAxisd(kPi / 18, Vec3::UnitX()));
    EXPECT_LT(angleBetween(r.sample.pose.orientation, expected), 1e-9);
    EXPECT_LT(r.sample.pose.position.norm(), 1e-15);

    // Older than `stale`: still valid, no longer tracked.
    r = device->pose(0, host->nowNs() + 61'000'000'000);
    EXPECT_TRUE(r.ok());
    EXPECT_FALSE(r.sample.has(VROC_POSE_ORIENTATION_TRACKED));
}

// The datagram is six little-endian IEEE doubles (opentrack writes its double[6] as it lies in
// memory; x86 and ARM are little-endian): built here byte by byte, not from a double array.
TEST(UdpPlugin, DatagramIsSixLittleEndianDoublesInOpentrackOrder) {
    static_assert(std::endian::native == std::endian::little, "opentrack's datagrams are native-endian");
    auto host = makeTestHost();
    const int port = freeLoopbackPort();
    auto device = host->open("udp", "port=" + std::to_string(port) + ",stale=60");
    const double values[6] = {-12.5, 3.0, 40.0, -45.0, 10.0, 5.0};  // TX TY TZ [cm], yaw pitch roll [deg]
    unsigned char bytes[48];
    for (int i = 0; i < 6; ++i) {
        const auto bits = std::bit_cast<uint64_t>(values[i]);
        for (int b = 0; b < 8; ++b) bytes[8 * i + b] = static_cast<unsigned char>(bits >> (8 * b));
    }
    Sender(port).send(bytes, sizeof bytes);
    ASSERT_TRUE(waitFor([&] { return device->pose(0, host->nowNs()).ok(); }));
    const PoseResult r = device->pose(0, host->nowNs());
    EXPECT_LT((r.sample.pose.position - Vec3(-0.40, 0.125, 0.03)).norm(), 1e-12);
    const Quat expected = Quat(Eigen::AngleAxisd(-kPi / 4, Vec3::UnitZ())) *
                          Quat(Eigen::AngleAxisd(kPi / 18, Vec3::UnitY())) *
                          Quat(Eigen::AngleAxisd(kPi / 36, Vec3::UnitX()));
    EXPECT_LT(angleBetween(r.sample.pose.orientation, expected), 1e-9);
}

// opentrack's output as it runs: 250 datagrams a second from its pipeline thread.
TEST(UdpPlugin, FollowsAnOpentrackStreamAt250Hz) {
    auto host = makeTestHost();
    const int port = freeLoopbackPort();
    auto device = host->open("udp", "port=" + std::to_string(port) + ",stale=60");
    // A head turning 60 deg/s and leaning 10 cm/s left for 0.3 s.
    auto head = [](double t) { return OpentrackPose{-10.0 * t, 0.0, 0.0, 60.0 * t, 0.0, 0.0}; };
    OpentrackSender sender(port);
    const auto begin = std::chrono::steady_clock::now();
    const int sent = sender.stream(head, 0.3);
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    EXPECT_EQ(sent, 75);                    // 0.3 s x 250 Hz
    EXPECT_GE(elapsed, 74 * 0.004 - 1e-3);  // paced, not a burst
    ASSERT_TRUE(waitFor([&] { return device->pose(0, host->nowNs()).sample.sequence == 75; }))
        << "received " << device->pose(0, host->nowNs()).sample.sequence;
    // The newest pose is the last one sent: t = 74 / 250 s.
    const PoseResult r = device->pose(0, host->nowNs());
    const double t = 74 / 250.0;
    EXPECT_LT((r.sample.pose.position - Vec3(0, 0.1 * t, 0)).norm(), 1e-12);  // -TX/100 = left
    EXPECT_LT(angleBetween(r.sample.pose.orientation, Quat(Eigen::AngleAxisd(60.0 * t * kPi / 180, Vec3::UnitZ()))),
              1e-9);
}

TEST(UdpPlugin, PortInUseIsAClearOpenError) {
    auto host = makeTestHost();
    const int port = freeLoopbackPort();
    auto first = host->open("udp", "port=" + std::to_string(port));
    try {
        host->open("udp", "port=" + std::to_string(port));
        FAIL();
    } catch (const std::exception& e) {
        EXPECT_NE(std::string(e.what()).find("cannot bind 127.0.0.1:" + std::to_string(port)), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace vroc::plugins::test
