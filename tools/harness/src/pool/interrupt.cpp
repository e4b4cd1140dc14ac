// SPDX-License-Identifier: MIT
#include "interrupt.h"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

namespace vroc::harness::pool_detail {
namespace {

// ---- What a signal handler may touch: async-signal-safe state only. ----
// The interrupt message is rebuilt after every finished run into the idle one of two buffers and
// published by flipping the index, so the handler always writes a whole message.
std::array<std::array<char, 4096>, 2> g_message{};
std::atomic<int> g_message_index{0};
std::array<std::atomic<pid_t>, kMaxLocalWorkers> g_children{};
// status.json's text beside each message buffer: built and published with it, written by the handler.
struct StatusText {
    std::array<char, 4096> path{};
    std::string text;
};
std::array<StatusText, 2> g_status{};
volatile sig_atomic_t g_handling = 0;

void onInterrupt(int) {
    if (g_handling) _exit(kExitInterrupted);
    g_handling = 1;
    for (auto& c : g_children) {
        const pid_t pid = c.load();
        if (pid > 0) kill(pid, SIGKILL);
    }
    const int k = g_message_index.load();
    const char* text = g_message[static_cast<std::size_t>(k)].data();
    [[maybe_unused]] ssize_t n = write(STDERR_FILENO, text, std::strlen(text));
    // status.json as of the last finished run (written between runs at most twice a second).
    const StatusText& status = g_status[static_cast<std::size_t>(k)];
    if (status.path[0] != '\0') {
        const int fd = open(status.path.data(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd >= 0) {
            n = write(fd, status.text.data(), status.text.size());
            close(fd);
        }
    }
    _exit(kExitInterrupted);
}

}  // namespace

void publishMessage(const std::string& text, const std::filesystem::path& status_path, const std::string& status_text) {
    const int next = 1 - g_message_index.load();
    StatusText& st = g_status[static_cast<std::size_t>(next)];
    const std::string p = status_path.string();
    const std::size_t m = std::min(p.size(), st.path.size() - 1);
    std::memcpy(st.path.data(), p.data(), m);
    st.path[m] = '\0';
    st.text = status_text;
    auto& buf = g_message[static_cast<std::size_t>(next)];
    const std::size_t n = std::min(text.size(), buf.size() - 1);
    std::memcpy(buf.data(), text.data(), n);
    buf[n] = '\0';
    g_message_index.store(next);
}

void registerChild(pid_t pid) {
    for (auto& c : g_children)
        if (c.load() == 0) {
            c.store(pid);
            break;
        }
}

void forgetChild(pid_t pid) {
    for (auto& c : g_children)
        if (c.load() == pid) c.store(0);
}

InterruptGuard::InterruptGuard() {
    struct sigaction sa {};
    sa.sa_handler = onInterrupt;
    sigemptyset(&sa.sa_mask);
    for (std::size_t i = 0; i < kSignals.size(); ++i) sigaction(kSignals[i], &sa, &old_[i]);
    // A worker that died shows as a failed write, not as SIGPIPE ending the dispatcher.
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigemptyset(&ignore.sa_mask);
    sigaction(SIGPIPE, &ignore, &old_pipe_);
}

InterruptGuard::~InterruptGuard() {
    for (std::size_t i = 0; i < kSignals.size(); ++i) sigaction(kSignals[i], &old_[i], nullptr);
    sigaction(SIGPIPE, &old_pipe_, nullptr);
}

void InterruptGuard::restoreDefaults() {
    for (int s : kSignals) signal(s, SIG_DFL);
    signal(SIGPIPE, SIG_DFL);
}

}  // namespace vroc::harness::pool_detail
