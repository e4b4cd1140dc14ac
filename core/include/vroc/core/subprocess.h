// SPDX-License-Identifier: MIT
// Starting helper programs (gnuplot, ffmpeg, chromium, vroc itself in tests) from an argument
// vector with posix_spawnp: no shell in between, so nothing needs quoting and no word of a path
// can be read as shell syntax. The one place that starts processes.
#pragma once

#include <sys/types.h>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace vroc {

struct SpawnOptions {
    /// Where the child's stdout / stderr go (created or truncated); empty: this process's own.
    /// The same path for both sends both to one file, in order.
    std::filesystem::path stdout_file;
    std::filesystem::path stderr_file;
    /// true: the child's stdin is a pipe fed by Subprocess::write; false: /dev/null.
    bool stdin_pipe = false;
    std::filesystem::path working_directory;   ///< empty: this process's
    bool new_process_group = false;            ///< the child leads a process group of its own
};

/// A running child process. Owns it: the destructor closes its stdin and waits for it.
class Subprocess {
public:
    /// Starts argv[0] (looked up in PATH when it has no '/') with `argv`. Throws RunError naming the
    /// program if it cannot be started (not installed, an output file not writable).
    explicit Subprocess(const std::vector<std::string>& argv, const SpawnOptions& options = {});
    ~Subprocess();
    Subprocess(const Subprocess&) = delete;
    Subprocess& operator=(const Subprocess&) = delete;

    /// Writes all of `size` bytes to the child's stdin (SpawnOptions::stdin_pipe). Returns false if
    /// the child closed it or exited (no SIGPIPE reaches this process).
    bool write(const void* data, std::size_t size);
    /// Closes stdin, waits for the child and returns its exit status: the exit code, or 128 + the
    /// signal number if a signal ended it (as a shell reports it). Idempotent.
    int wait();
    /// The exit status if the child has ended (reaping it), nothing while it runs.
    std::optional<int> poll();
    pid_t pid() const { return pid_; }

private:
    pid_t pid_ = -1;
    int stdin_fd_ = -1;
    std::optional<int> status_;
};

/// Runs `argv` to its end (stdin /dev/null); returns its exit status as Subprocess::wait.
/// Throws RunError if it cannot be started.
int runProcess(const std::vector<std::string>& argv, const SpawnOptions& options = {});

}  // namespace vroc
