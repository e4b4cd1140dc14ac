// SPDX-License-Identifier: MIT
// A small stand-in for spacenavd, the daemon side of the AF_UNIX protocol that libspnav speaks
// (FreeSpacenav/spacenavd src/proto_unix.c and proto.h; libspnav 1.0 src/spnav.c), so that the
// real client library runs in the tests. It listens on a socket path, serves one client at a time
// and:
//  - protocol 0 (spacenavd before 1.0): every 4-byte message from the client is a float
//    sensitivity; libspnav's protocol request (int32 0x7faa5501) is taken as one too and left
//    unanswered, as an old daemon does, so libspnav times out (300 ms), sends the sensitivity 1.0
//    and stays at protocol 0;
//  - protocol 1: the first message 0x7faa55vv asks for protocol vv; the daemon answers with the
//    version it speaks (min(vv, 1)) in the same form and from then on reads 32-byte requests
//    {int32 type, int32 data[7]}: REQ_SET_NAME (0x1000, a string in 24-byte chunks, data[6] =
//    remaining length, bit 16 set on continuation packets, no answer) and REQ_SET_EVMASK (0x1003,
//    answered with data[6] = 0); any other request is answered with status -1, as spacenavd does.
// Events go out as spacenavd's 32-byte packets {int32 type, int32 data[7]}: motion = {0, x, y, z,
// rx, ry, rz, period [ms]}, button = {1 press | 2 release, number, 0...}; with protocol 1 only the
// event kinds in the client's event mask are sent.
#pragma once

#include <poll.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace vroc::plugins::test {

class SpacenavdTestDaemon {
public:
    static constexpr int32_t kReqTag = 0x7faa0000, kReqChangeProto = 0x5500;
    static constexpr int32_t kReqSetName = 0x1000, kReqSetEvmask = 0x1003;
    static constexpr int32_t kEvmaskMotion = 0x01, kEvmaskButton = 0x02, kEvmaskDev = 0x04;

    /// Listens on `path` (replacing a stale socket file) speaking protocol 0 or 1.
    SpacenavdTestDaemon(std::string path, int protocol) : path_(std::move(path)), protocol_(protocol) {
        if (path_.size() >= sizeof(sockaddr_un::sun_path)) throw std::runtime_error("socket path too long: " + path_);
        listen_fd_ = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
        if (listen_fd_ < 0) throw std::runtime_error(std::string("socket: ") + std::strerror(errno));
        unlink(path_.c_str());
        sockaddr_un address{};
        address.sun_family = AF_UNIX;
        std::strncpy(address.sun_path, path_.c_str(), sizeof address.sun_path - 1);
        if (bind(listen_fd_, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 ||
            listen(listen_fd_, 4) != 0) {
            const std::string why = std::strerror(errno);
            close(listen_fd_);
            throw std::runtime_error("cannot listen on " + path_ + ": " + why);
        }
        thread_ = std::thread([this] { serve(); });
    }

    ~SpacenavdTestDaemon() {
        running_ = false;
        thread_.join();
        disconnect();
        close(listen_fd_);
        unlink(path_.c_str());
    }

    const std::string& path() const { return path_; }

    /// Sends a motion event (counts in spacenavd's frame: x right, y up, z forward).
    void sendMotion(const std::array<int32_t, 6>& counts, int32_t period_ms = 16) {
        if (protocol_ >= 1 && !(evmask_.load() & kEvmaskMotion)) return;
        int32_t packet[8] = {0, counts[0], counts[1], counts[2], counts[3], counts[4], counts[5], period_ms};
        write(packet);
    }
    void sendButton(int32_t number, bool press) {
        if (protocol_ >= 1 && !(evmask_.load() & kEvmaskButton)) return;
        int32_t packet[8] = {press ? 1 : 2, number, 0, 0, 0, 0, 0, 0};
        write(packet);
    }
    /// Closes the client's connection (spacenavd stopped).
    void disconnect() {
        std::lock_guard lock(mutex_);
        if (client_fd_ >= 0) close(client_fd_);
        client_fd_ = -1;
    }

    // What the client sent, for the test to check.
    bool connected() const { return connected_.load(); }
    int negotiatedProtocol() const { return negotiated_.load(); }
    int32_t evmask() const { return evmask_.load(); }
    std::string clientName() const {
        std::lock_guard lock(mutex_);
        return name_;
    }
    std::vector<uint32_t> firstMessages() const {  ///< the 4-byte messages received in protocol 0
        std::lock_guard lock(mutex_);
        return messages_;
    }
    std::vector<int32_t> otherRequests() const {
        std::lock_guard lock(mutex_);
        return other_requests_;
    }

private:
    void write(const int32_t (&packet)[8]) {
        std::lock_guard lock(mutex_);
        if (client_fd_ < 0) throw std::runtime_error("spacenavd test daemon: no client");
        if (::send(client_fd_, packet, sizeof packet, MSG_NOSIGNAL) != static_cast<ssize_t>(sizeof packet))
            throw std::runtime_error("spacenavd test daemon: short write");
    }

    void serve() {
        std::vector<unsigned char> pending;
        int fd = -1;
        while (running_) {
            if (fd < 0) {
                pollfd pfd{listen_fd_, POLLIN, 0};
                if (poll(&pfd, 1, 20) <= 0) continue;
                fd = accept4(listen_fd_, nullptr, nullptr, SOCK_CLOEXEC);
                if (fd < 0) continue;
                std::lock_guard lock(mutex_);
                client_fd_ = fd;
                connected_ = true;
                continue;
            }
            {
                std::lock_guard lock(mutex_);
                if (client_fd_ != fd) {  // disconnect() closed it: wait for the next client
                    fd = -1;
                    pending.clear();
                    negotiated_ = 0;
                    continue;
                }
            }
            pollfd pfd{fd, POLLIN, 0};
            if (poll(&pfd, 1, 20) <= 0) continue;
            unsigned char buffer[256];
            const ssize_t n = recv(fd, buffer, sizeof buffer, MSG_DONTWAIT);
            if (n == 0) {  // the client closed the connection
                disconnect();
                continue;
            }
            if (n < 0) continue;
            pending.insert(pending.end(), buffer, buffer + n);
            while (consume(pending, fd)) {
            }
        }
    }

    // Handles one complete message from the front of `pending`; false if more bytes are needed.
    bool consume(std::vector<unsigned char>& pending, int fd) {
        if (negotiated_ == 0) {
            if (pending.size() < 4) return false;
            uint32_t message;
            std::memcpy(&message, pending.data(), 4);
            pending.erase(pending.begin(), pending.begin() + 4);
            {
                std::lock_guard lock(mutex_);
                messages_.push_back(message);
            }
            if (protocol_ >= 1 && (message & 0xffffff00u) == static_cast<uint32_t>(kReqTag | kReqChangeProto)) {
                const int version = std::min<int>(message & 0xff, protocol_);
                const int32_t answer = kReqTag | kReqChangeProto | version;
                evmask_ = kEvmaskMotion | kEvmaskButton | kEvmaskDev;  // spacenavd's default for v1 clients
                reply(fd, &answer, sizeof answer);
                negotiated_ = version;
            }
            return true;  // protocol 0: a sensitivity; nothing to answer
        }
        if (pending.size() < 32) return false;
        int32_t request[8];
        std::memcpy(request, pending.data(), 32);
        pending.erase(pending.begin(), pending.begin() + 32);
        switch (request[0] & 0xffff) {
            case kReqSetName: {
                const int remaining = request[7] & 0xffff;
                const int chunk = std::min(remaining, 24);
                std::lock_guard lock(mutex_);
                if (!(request[7] & 0x10000)) name_.clear();  // first packet
                name_.append(reinterpret_cast<const char*>(request + 1), static_cast<size_t>(chunk));
                break;  // spacenavd sends no answer
            }
            case kReqSetEvmask:
                evmask_ = request[1];
                request[7] = 0;
                reply(fd, request, sizeof request);
                break;
            default: {
                {
                    std::lock_guard lock(mutex_);
                    other_requests_.push_back(request[0]);
                }
                request[7] = -1;
                reply(fd, request, sizeof request);
            }
        }
        return true;
    }

    void reply(int fd, const void* data, size_t size) {
        std::lock_guard lock(mutex_);
        if (fd == client_fd_) (void)::send(fd, data, size, MSG_NOSIGNAL);
    }

    std::string path_;
    int protocol_;
    int listen_fd_ = -1;
    int client_fd_ = -1;  // guarded by mutex_
    mutable std::mutex mutex_;
    std::thread thread_;
    std::atomic<bool> running_{true};
    std::atomic<bool> connected_{false};
    std::atomic<int> negotiated_{0};
    std::atomic<int32_t> evmask_{0};
    std::string name_;                    // guarded by mutex_
    std::vector<uint32_t> messages_;      // guarded by mutex_
    std::vector<int32_t> other_requests_; // guarded by mutex_
};

}  // namespace vroc::plugins::test
