// SPDX-License-Identifier: MIT
#include "spacenav_connection.h"

#include <spnav.h>
#include <sys/socket.h>
#include <sys/un.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <optional>
#include <stdexcept>

namespace vroc::plugins::spacenav {
namespace {

std::mutex g_mutex;   // guards g_open and the environment while spnav_open reads it
bool g_open = false;  // libspnav's globals are in use

std::string peerPath(int fd) {
    sockaddr_un address{};
    socklen_t length = sizeof address;
    if (fd < 0 || getpeername(fd, reinterpret_cast<sockaddr*>(&address), &length) != 0) return {};
    if (length <= offsetof(sockaddr_un, sun_path)) return {};
    return std::string(address.sun_path, strnlen(address.sun_path, length - offsetof(sockaddr_un, sun_path)));
}

bool samePath(const std::string& a, const std::string& b) {
    if (a == b) return true;
    std::error_code ec1, ec2;
    const auto ca = std::filesystem::weakly_canonical(a, ec1), cb = std::filesystem::weakly_canonical(b, ec2);
    return !ec1 && !ec2 && ca == cb;
}

// Sets SPNAV_SOCKET while alive and puts the previous value (or its absence) back.
class ScopedSocketVariable {
public:
    explicit ScopedSocketVariable(const std::string& path) {
        if (path.empty()) return;
        if (const char* old = std::getenv("SPNAV_SOCKET")) previous_ = old;
        setenv("SPNAV_SOCKET", path.c_str(), 1);
        active_ = true;
    }
    ~ScopedSocketVariable() {
        if (!active_) return;
        if (previous_) setenv("SPNAV_SOCKET", previous_->c_str(), 1);
        else unsetenv("SPNAV_SOCKET");
    }

private:
    bool active_ = false;
    std::optional<std::string> previous_;
};

}  // namespace

SpacenavConnection::SpacenavConnection(const std::string& socket) {
    std::lock_guard lock(g_mutex);
    if (g_open)
        throw std::runtime_error("libspnav allows one connection per process and it is already open "
                                 "(one spacenav device at a time)");
    int rc = -1, error = 0;
    {
        ScopedSocketVariable variable(socket);
        errno = 0;
        rc = spnav_open();
        error = errno;
    }
    const std::string where = socket.empty() ? "SPNAV_SOCKET, /etc/spnavrc 'socket', /var/run/spnav.sock" : socket;
    if (rc != 0)
        throw std::runtime_error("cannot connect to spacenavd (tried " + where + ")" +
                                 (error ? std::string(": ") + std::strerror(error) : std::string()));
    fd_ = spnav_fd();
    peer_ = peerPath(fd_);
    // libspnav falls back to other sockets when the asked one fails: a daemon other than the one
    // asked for is not what the user meant.
    if (!socket.empty() && !samePath(peer_, socket)) {
        spnav_close();
        throw std::runtime_error("no spacenavd at " + socket + " (libspnav connected to '" + peer_ + "' instead)");
    }
    protocol_ = spnav_protocol();
    if (protocol_ >= 1) {
        spnav_client_name("vroc");
        if (spnav_evmask(SPNAV_EVMASK_MOTION | SPNAV_EVMASK_BUTTON) != 0) {
            spnav_close();
            throw std::runtime_error("spacenavd at " + peer_ + " refused the event mask request");
        }
    }
    g_open = true;
}

SpacenavConnection::~SpacenavConnection() {
    std::lock_guard lock(g_mutex);
    spnav_close();
    g_open = false;
}

bool SpacenavConnection::poll(SpacenavEvent& out) {
    spnav_event event;
    if (spnav_poll_event(&event) <= 0) return false;
    out = SpacenavEvent{};
    if (event.type == SPNAV_EVENT_MOTION) {
        out.type = SpacenavEvent::Type::Motion;
        const spnav_event_motion& m = event.motion;
        out.counts = {m.x, m.y, m.z, m.rx, m.ry, m.rz};
    } else if (event.type == SPNAV_EVENT_BUTTON) {
        out.type = SpacenavEvent::Type::Button;
        out.button = event.button.bnum;
        out.pressed = event.button.press != 0;
    }
    return true;
}

}  // namespace vroc::plugins::spacenav
