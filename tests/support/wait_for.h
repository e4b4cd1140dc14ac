// SPDX-License-Identifier: MIT
// Waiting for an asynchronous effect in a test (a plugin's reader thread noticing a datagram or a
// closed connection): poll until it shows, within a bounded time, instead of checking at once
// (issue 26: a check that counted at once failed on a loaded machine).
#pragma once

#include <chrono>
#include <thread>

namespace vroc::test {

/// Polls `done` every 2 ms until it returns true (then true) or `timeout` passes (then done()'s
/// last answer). The default is generous: the machine may be busy with a parallel build.
template <class F>
bool waitFor(F&& done, std::chrono::milliseconds timeout = std::chrono::seconds(10)) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < deadline) {
        if (done()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return done();
}

}  // namespace vroc::test
