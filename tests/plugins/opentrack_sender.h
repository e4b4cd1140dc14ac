// SPDX-License-Identifier: MIT
// Sends head poses the way opentrack's "UDP over network" output does, for tests of the `udp`
// plugin and of `vroc play` with a live head tracker.
//
// What opentrack does (opentrack/opentrack):
//  - proto-udp/ftnoir_protocol_ftn.cpp, udp::pose(const double* headpose): one datagram per call,
//    writeDatagram((const char*)headpose, sizeof(double[6])) - the six doubles as they lie in
//    memory (native byte order: little-endian on x86 and ARM), no header, 48 bytes;
//  - api/plugin-api.hpp: the order is enum Axis {TX, TY, TZ, Yaw, Pitch, Roll}; translation in
//    centimetres, rotation in degrees; IProtocol::pose is "called 250 times a second";
//  - logic/pipeline.cpp, pipeline::run(): `constexpr ms interval{4}` - one pipeline step (tracker
//    read, filter, mapping, protocol->pose) every 4 ms, sleeping clamp(interval - backlog, 0, 10 ms)
//    so that a late step is made up by the next ones. Here: absolute deadlines every 4 ms on
//    steady_clock, sending at once when late, which keeps the same long-run rate.
//  - settings default port 4242 (ip 192.168.0.2 in opentrack's dialog; tests use 127.0.0.1).
#pragma once

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <thread>

namespace vroc::plugins::test {

/// One opentrack pose: TX, TY, TZ [cm], yaw, pitch, roll [deg] (opentrack's Axis order).
using OpentrackPose = std::array<double, 6>;

class OpentrackSender {
public:
    static constexpr double kRateHz = 250.0;                          ///< opentrack's pipeline rate
    static constexpr std::chrono::microseconds kInterval{4000};       ///< 1 / kRateHz
    static constexpr size_t kDatagramSize = sizeof(double[6]);        ///< 48 bytes

    /// A UDP socket sending to address:port (host byte order; default 127.0.0.1).
    explicit OpentrackSender(int port, uint32_t address = INADDR_LOOPBACK) : fd_(socket(AF_INET, SOCK_DGRAM, 0)) {
        if (fd_ < 0) throw std::runtime_error(std::string("opentrack sender: socket: ") + std::strerror(errno));
        to_.sin_family = AF_INET;
        to_.sin_port = htons(static_cast<uint16_t>(port));
        to_.sin_addr.s_addr = htonl(address);
    }
    ~OpentrackSender() { close(fd_); }
    OpentrackSender(const OpentrackSender&) = delete;
    OpentrackSender& operator=(const OpentrackSender&) = delete;

    /// One datagram, byte for byte what opentrack's udp::pose writes. Returns false if not sent.
    bool send(const OpentrackPose& pose) {
        const double* headpose = pose.data();
        return sendto(fd_, reinterpret_cast<const char*>(headpose), kDatagramSize, 0,
                      reinterpret_cast<const sockaddr*>(&to_), sizeof to_) == static_cast<ssize_t>(kDatagramSize);
    }

    /// Sends pose_at(t) for t = 0, 4 ms, 8 ms, ... while t < duration_s [s] (or until *stop), paced
    /// at 250 Hz from now on steady_clock. Returns the number of datagrams sent.
    template <class PoseAt>
    int stream(PoseAt&& pose_at, double duration_s, const std::atomic<bool>* stop = nullptr) {
        const auto start = std::chrono::steady_clock::now();
        int sent = 0;
        for (int64_t k = 0;; ++k) {
            const double t = static_cast<double>(k) / kRateHz;
            if (t >= duration_s || (stop && stop->load())) break;
            std::this_thread::sleep_until(start + k * kInterval);
            sent += send(pose_at(t)) ? 1 : 0;
        }
        return sent;
    }

private:
    int fd_;
    sockaddr_in to_{};
};

}  // namespace vroc::plugins::test
