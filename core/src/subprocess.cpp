// SPDX-License-Identifier: MIT
#include "vroc/core/subprocess.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>

#include "vroc/core/errors.h"

extern char** environ;

namespace vroc {
namespace {

int exitStatus(int status) {
    if (WIFEXITED(status)) return WEXITSTATUS(status);
    if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
    return -1;
}

// A file descriptor closed on scope exit.
struct Fd {
    int fd = -1;
    ~Fd() {
        if (fd >= 0) ::close(fd);
    }
};

int openOutput(const std::filesystem::path& path, const std::string& program) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) throw RunError("cannot start " + program + ": cannot write " + path.string() + ": " + std::strerror(errno));
    return fd;
}

// posix_spawn attribute and file-action objects, destroyed on scope exit.
struct SpawnSetup {
    posix_spawn_file_actions_t actions;
    posix_spawnattr_t attr;
    SpawnSetup() {
        posix_spawn_file_actions_init(&actions);
        posix_spawnattr_init(&attr);
    }
    ~SpawnSetup() {
        posix_spawn_file_actions_destroy(&actions);
        posix_spawnattr_destroy(&attr);
    }
};

}  // namespace

Subprocess::Subprocess(const std::vector<std::string>& argv, const SpawnOptions& options) {
    if (argv.empty() || argv[0].empty()) throw RunError("Subprocess: no program given");
    const std::string& program = argv[0];
    SpawnSetup setup;
    Fd out, err, in_read, in_write, null_in;
    if (options.stdin_pipe) {
        int fds[2];
        if (::pipe2(fds, O_CLOEXEC) != 0) throw RunError("cannot start " + program + ": pipe: " + std::strerror(errno));
        in_read.fd = fds[0];
        in_write.fd = fds[1];
        posix_spawn_file_actions_adddup2(&setup.actions, in_read.fd, STDIN_FILENO);
    } else {
        posix_spawn_file_actions_addopen(&setup.actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    }
    if (!options.stdout_file.empty()) {
        out.fd = openOutput(options.stdout_file, program);
        posix_spawn_file_actions_adddup2(&setup.actions, out.fd, STDOUT_FILENO);
    }
    if (!options.stderr_file.empty()) {
        if (options.stderr_file == options.stdout_file) {
            posix_spawn_file_actions_adddup2(&setup.actions, STDOUT_FILENO, STDERR_FILENO);
        } else {
            err.fd = openOutput(options.stderr_file, program);
            posix_spawn_file_actions_adddup2(&setup.actions, err.fd, STDERR_FILENO);
        }
    }
    if (!options.working_directory.empty())
        posix_spawn_file_actions_addchdir_np(&setup.actions, options.working_directory.c_str());

    // The child starts with default dispositions and no blocked signals, whatever this process
    // (or the thread starting it) ignores or blocks at the moment, e.g. SIGPIPE while writing.
    short flags = POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK;
    sigset_t defaults, none;
    sigemptyset(&defaults);
    for (int s : {SIGPIPE, SIGINT, SIGTERM, SIGCHLD}) sigaddset(&defaults, s);
    sigemptyset(&none);
    posix_spawnattr_setsigdefault(&setup.attr, &defaults);
    posix_spawnattr_setsigmask(&setup.attr, &none);
    if (options.new_process_group) {
        flags |= POSIX_SPAWN_SETPGROUP;
        posix_spawnattr_setpgroup(&setup.attr, 0);
    }
    posix_spawnattr_setflags(&setup.attr, flags);

    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    const int rc = ::posix_spawnp(&pid_, program.c_str(), &setup.actions, &setup.attr, args.data(), environ);
    if (rc != 0) {
        pid_ = -1;
        throw RunError("cannot start " + program + ": " + std::strerror(rc));
    }
    stdin_fd_ = in_write.fd;
    in_write.fd = -1;
}

Subprocess::~Subprocess() { wait(); }

bool Subprocess::write(const void* data, std::size_t size) {
    if (stdin_fd_ < 0) return false;
    // A child that stopped reading must show as a failed write, not as SIGPIPE ending this
    // process: block it in this thread, and take away the one a failed write left pending.
    sigset_t pipe_set, old_mask, pending;
    sigemptyset(&pipe_set);
    sigaddset(&pipe_set, SIGPIPE);
    pthread_sigmask(SIG_BLOCK, &pipe_set, &old_mask);
    sigpending(&pending);
    const bool was_pending = sigismember(&pending, SIGPIPE) == 1;
    const char* p = static_cast<const char*>(data);
    bool ok = true;
    while (size > 0) {
        const ssize_t n = ::write(stdin_fd_, p, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            ok = false;
            break;
        }
        p += n;
        size -= static_cast<std::size_t>(n);
    }
    if (!ok && !was_pending) {
        const timespec zero{0, 0};
        while (sigtimedwait(&pipe_set, nullptr, &zero) < 0 && errno == EINTR) {}
    }
    pthread_sigmask(SIG_SETMASK, &old_mask, nullptr);
    return ok;
}

int Subprocess::wait() {
    if (stdin_fd_ >= 0) {
        ::close(stdin_fd_);
        stdin_fd_ = -1;
    }
    if (status_ || pid_ < 0) return status_.value_or(-1);
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0) {
        if (errno != EINTR) {
            status_ = -1;
            return -1;
        }
    }
    status_ = exitStatus(status);
    return *status_;
}

std::optional<int> Subprocess::poll() {
    if (status_ || pid_ < 0) return status_;
    int status = 0;
    const pid_t r = ::waitpid(pid_, &status, WNOHANG);
    if (r == pid_) status_ = exitStatus(status);
    else if (r < 0 && errno != EINTR) status_ = -1;
    return status_;
}

int runProcess(const std::vector<std::string>& argv, const SpawnOptions& options) {
    SpawnOptions o = options;
    o.stdin_pipe = false;
    return Subprocess(argv, o).wait();
}

}  // namespace vroc
