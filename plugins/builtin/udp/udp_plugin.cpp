// SPDX-License-Identifier: MIT
// `udp`: receives opentrack UDP datagrams on 127.0.0.1:<port>. A receiver thread keeps only the
// newest valid datagram; short/long datagrams and any non-finite value are dropped (and logged
// through the host). The pose is stamped with the host time of arrival minus the configured
// latency; it stays valid but loses its TRACKED flags once older than `stale`.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <mutex>
#include <thread>

#include "opentrack_datagram.h"
#include "plugin_sdk.h"
#include "pose_math.h"

namespace vroc::plugins::udp {
using namespace plugin_sdk;

namespace {

constexpr const char* kHelp =
    "port=4242: UDP port on 127.0.0.1; latency=0: seconds from measurement to arrival; "
    "stale=0.5: seconds after which the pose is no longer tracked";
constexpr int kLoggedDrops = 10;  // then drops are only counted

class UdpDevice final : public Device {
public:
    UdpDevice(int port, int64_t latency_ns, int64_t stale_ns) : latency_ns_(latency_ns), stale_ns_(stale_ns) {
        fd_ = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
        if (fd_ < 0) throw std::runtime_error(std::string("socket: ") + std::strerror(errno));
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_port = htons(static_cast<uint16_t>(port));
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);  // loopback only, never the network
        if (bind(fd_, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
            const std::string why = std::strerror(errno);
            close(fd_);
            throw std::runtime_error("cannot bind 127.0.0.1:" + std::to_string(port) + ": " + why);
        }
    }
    ~UdpDevice() override {
        stop();
        close(fd_);
    }

    int32_t start() override {
        if (!thread_.joinable()) {
            running_ = true;
            thread_ = std::thread([this] { receive(); });
        }
        return VROC_OK;
    }
    int32_t stop() override {
        running_ = false;
        if (thread_.joinable()) thread_.join();
        return VROC_OK;
    }

    int32_t pose(uint32_t sensor, int64_t at_time_ns, VrocPoseSample& out) override {
        if (sensor != 0) return setError(VROC_ERROR_INVALID_ARGUMENT, "udp: only sensor 0 exists");
        std::array<double, 6> values;
        int64_t arrival;
        uint64_t sequence;
        {
            std::lock_guard lock(mutex_);
            if (sequence_ == 0) return setError(VROC_ERROR_NO_DATA, "udp: no datagram received yet");
            values = newest_;
            arrival = arrival_ns_;
            sequence = sequence_;
        }
        const OpentrackPose p = opentrackToPose(values);
        const bool fresh = at_time_ns - arrival <= stale_ns_;
        writePose(out, arrival - latency_ns_, 0, p.position, p.orientation, fresh ? kPoseValidTracked : kPoseValid);
        out.sequence = sequence;
        return VROC_OK;
    }

private:
    void receive() {
        while (running_) {
            pollfd pfd{fd_, POLLIN, 0};
            if (poll(&pfd, 1, 20) <= 0) continue;  // wake up regularly to see stop()
            unsigned char buffer[128];
            const ssize_t n = recv(fd_, buffer, sizeof buffer, MSG_DONTWAIT);
            if (n < 0) continue;
            accept(buffer, static_cast<size_t>(n));
        }
    }

    void accept(const unsigned char* buffer, size_t size) {
        std::array<double, 6> values;
        if (std::string why = decodeOpentrackDatagram(buffer, size, values); !why.empty()) return drop(why);
        const int64_t now = nowNs();
        std::lock_guard lock(mutex_);
        newest_ = values;
        arrival_ns_ = now;
        ++sequence_;
    }

    void drop(const std::string& why) {
        const int count = ++drops_;
        if (count <= kLoggedDrops)
            log(VROC_LOG_WARNING, "dropped " + why + " (" + std::to_string(count) + " dropped so far)");
    }

    int fd_ = -1;
    int64_t latency_ns_, stale_ns_;
    std::atomic<bool> running_{false};
    std::atomic<int> drops_{0};
    std::thread thread_;
    std::mutex mutex_;
    std::array<double, 6> newest_{};
    int64_t arrival_ns_ = 0;
    uint64_t sequence_ = 0;  // accepted datagrams
};

void describe(uint32_t, VrocDeviceDesc& out) {
    out.kind = VROC_DEVICE_HEAD_TRACKER;
    out.sensor_count = 1;
    out.button_count = 0;
    out.axis_count = 0;
    out.caps = VROC_CAP_POSE_SOURCE | VROC_CAP_POSITION | VROC_CAP_ORIENTATION;
    out.nominal_rate_hz = 0;
    out.nominal_latency_ns = 0;
    out.name = "opentrack UDP receiver";
    out.options_help = kHelp;
}

std::unique_ptr<Device> create(uint32_t, Options& o) {
    const int port = static_cast<int>(o.getInt("port", 4242, 1, 65535));
    const int64_t latency = nsOf(o.getDouble("latency", 0.0, 0.0, 10.0));
    const int64_t stale = nsOf(o.getDouble("stale", 0.5, 0.0, 3600.0));
    return std::make_unique<UdpDevice>(port, latency, stale);
}

const PluginDefinition kDefinition = {"udp", "1.0.0", "opentrack UDP receiver (48-byte datagrams, 127.0.0.1)", 1,
                                      describe, create};

}  // namespace
}  // namespace vroc::plugins::udp

VROC_DEFINE_PLUGIN(vroc::plugins::udp::kDefinition)
