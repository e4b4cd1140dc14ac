// SPDX-License-Identifier: MIT
// What the run pool does when it is interrupted (Ctrl-C, SIGTERM from a cancelled job or from
// Open MPI after a lost rank, SIGHUP): kill the local workers, print the message naming the runs
// that did not finish, write the latest status.json and exit with code 3 (docs/harness.md,
// "Interrupted runs and --resume"). The handler touches only async-signal-safe state.
#pragma once

#include <array>
#include <filesystem>
#include <signal.h>
#include <string>
#include <sys/types.h>

namespace vroc::harness::pool_detail {

constexpr int kMaxLocalWorkers = 256;  ///< forked workers at once, per process
constexpr int kExitInterrupted = 3;    ///< docs/cli.md: 3 = failure while running, interruption included

/// Publishes the message an interrupt prints and the status.json text it writes to `status_path`:
/// built into the idle one of two buffers and published by flipping the index, so the handler
/// always writes a whole message.
void publishMessage(const std::string& text, const std::filesystem::path& status_path, const std::string& status_text);

/// A forked worker the handler kills on an interrupt; forgotten once it has been reaped.
void registerChild(pid_t pid);
void forgetChild(pid_t pid);

/// Installs the interrupt handler for the life of a phase, restoring the previous ones after.
class InterruptGuard {
public:
    InterruptGuard();
    ~InterruptGuard();
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;
    /// In a forked worker: the default dispositions again (the parent handles interrupts).
    static void restoreDefaults();

private:
    static constexpr std::array<int, 3> kSignals{SIGINT, SIGTERM, SIGHUP};
    std::array<struct sigaction, 3> old_{};
    struct sigaction old_pipe_ {};
};

}  // namespace vroc::harness::pool_detail
