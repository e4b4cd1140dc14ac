// SPDX-License-Identifier: MIT
// The process's one connection to spacenavd through libspnav (libspnav keeps its socket and event
// queue in globals, so a process has at most one; opening a second is an error, not a silent
// takeover).
//
// Where libspnav 1.0 connects (spnav_open): the path in the environment variable SPNAV_SOCKET if
// set and connectable, else `socket = PATH` from /etc/spnavrc, else /var/run/spnav.sock. There is
// no call taking a path, so a path given here is put into SPNAV_SOCKET for the duration of
// spnav_open (under a process-wide lock; the previous value is restored) and the peer's address is
// checked afterwards, so that libspnav's fallback to another daemon is an error. Then libspnav
// sends the protocol request (int32 0x7faa5501) and waits up to 300 ms for the daemon's answer: a
// spacenavd >= 1.0 answers with the protocol it speaks (1), an older one stays silent (protocol 0,
// and libspnav then sends the float sensitivity 1.0 that v0 daemons expect). With protocol 1 the
// connection names the client ("vroc", REQ_SET_NAME) and asks for motion and button events only
// (REQ_SET_EVMASK).
//
// Not thread-safe: one thread opens, then one thread polls (the device's reader thread), then the
// opener closes after that thread has stopped.
#pragma once

#include <array>
#include <string>

namespace vroc::plugins::spacenav {

/// One event as libspnav decoded it (spnav.h stays out of this header: it pulls in Xlib, whose
/// macros clash with Eigen).
struct SpacenavEvent {
    enum class Type { Motion, Button, Other } type = Type::Other;
    std::array<int, 6> counts{};  ///< motion: x, y, z, rx, ry, rz in spacenavd's frame
    int button = -1;              ///< button: its number
    bool pressed = false;         ///< button: pressed (true) or released
};

class SpacenavConnection {
public:
    /// `socket`: the daemon's socket path, or "" for libspnav's own search. Throws
    /// std::runtime_error naming the path and the reason.
    explicit SpacenavConnection(const std::string& socket);
    ~SpacenavConnection();
    SpacenavConnection(const SpacenavConnection&) = delete;
    SpacenavConnection& operator=(const SpacenavConnection&) = delete;

    int fd() const { return fd_; }
    int protocol() const { return protocol_; }      ///< 0 or 1, as negotiated by libspnav
    const std::string& peer() const { return peer_; }  ///< the daemon's socket path
    /// The next queued event without blocking (spnav_poll_event); false if there is none.
    bool poll(SpacenavEvent& event);

private:
    int fd_ = -1;
    int protocol_ = 0;
    std::string peer_;
};

}  // namespace vroc::plugins::spacenav
