// SPDX-License-Identifier: MIT
// The dispatcher's local workers (dispatcher.h): processes forked once per phase, fed jobs over pipes.
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <poll.h>
#include <string_view>
#include <sys/wait.h>
#include <unistd.h>

#include "dispatcher.h"
#include "interrupt.h"
#include "pipe_frames.h"
#include "run_files.h"
#include "vroc/core/errors.h"

namespace vroc::harness::pool_detail {

void Dispatcher::spawnWorker() {
    int down[2], up[2];
    if (pipe(down) != 0 || pipe(up) != 0) throw RunError(std::string("pipe failed: ") + std::strerror(errno));
    std::fflush(nullptr);  // nothing buffered is written twice by the child
    const pid_t pid = fork();
    if (pid < 0) throw RunError(std::string("fork failed: ") + std::strerror(errno));
    if (pid == 0) {
        InterruptGuard::restoreDefaults();
        close(down[1]);
        close(up[0]);
        for (const LocalWorker& w : workers_) {
            close(w.to);
            close(w.from);
        }
        serveAsLocalWorker(down[0], up[1]);
        _exit(0);  // no destructors, no atexit handlers of the parent (MPI among them)
    }
    close(down[0]);
    close(up[1]);
    registerChild(pid);
    workers_.push_back({pid, down[1], up[0], std::nullopt, {}, {}});
}

void Dispatcher::serveAsLocalWorker(int in, int out) {
    std::string command;
    while (readFrame(in, command)) {
        const long i = std::stol(command);
        if (i < 0) return;
        const std::size_t nl = command.find('\n');
        if (nl != std::string::npos && on_dependency_)
            for (const Json& d : Json::parse(command.substr(nl + 1))) on_dependency_(d[0].get<std::size_t>(), d[1]);
        auto [ok, text] = runHere(jobs_[static_cast<std::size_t>(i)]);
        if (ok && o_.runs_dir.empty()) {  // nothing kept on disk: the result travels over the pipe
            if (!writeFrame(out, "ok\n" + text)) return;
            continue;
        }
        if (ok) {
            try {
                writeRunFile(o_.runs_dir, jobs_[static_cast<std::size_t>(i)].id, plan_hash_, text);
            } catch (...) {
                ok = false;
                text = "could not write the result: " + errorText(std::current_exception());
            }
        }
        if (!writeFrame(out, ok ? std::string("ok") : "fail\n" + text)) return;
    }
}

void Dispatcher::assignLocal(LocalWorker& w, std::size_t i) {
    std::string deps = "[";
    for (std::size_t a : jobs_[i].after)
        if (w.sent.insert(a).second)
            deps += (deps.size() > 1 ? ",[" : "[") + std::to_string(a) + "," + *results_[a] + "]";
    w.job = i;
    w.start = Clock::now();
    if (!writeFrame(w.to, std::to_string(i) + "\n" + deps + "]")) workerDied(w);
}

bool Dispatcher::collectLocal(int timeout_ms) {
    std::vector<pollfd> fds;
    for (const LocalWorker& w : workers_)
        if (w.job) fds.push_back({w.from, POLLIN, 0});
    if (fds.empty()) return false;
    if (poll(fds.data(), fds.size(), timeout_ms) <= 0) return false;
    bool any = false;
    for (LocalWorker& w : workers_) {
        if (!w.job) continue;
        pollfd* f = nullptr;
        for (pollfd& p : fds)
            if (p.fd == w.from) f = &p;
        if (!f || !(f->revents & (POLLIN | POLLHUP | POLLERR))) continue;
        std::string answer;
        if (!readFrame(w.from, answer)) {
            workerDied(w);
            any = true;
            continue;
        }
        const std::size_t i = *w.job;
        w.job.reset();
        if (answer.rfind("ok\n", 0) == 0) {  // no runs_dir: the result itself, normalised as a file's is
            finish(i, true, Json::parse(std::string_view(answer).substr(3)).dump(), w.start, false);
        } else if (answer == "ok") {
            const std::optional<Json> r = readRunFile(o_.runs_dir / (jobs_[i].id + ".json"), jobs_[i].id, plan_hash_);
            if (r)
                finish(i, true, r->dump(), w.start, false);
            else
                finish(i, false, "the worker answered without writing its result", w.start, false);
        } else {
            finish(i, false, answer.substr(answer.find('\n') + 1), w.start, false);
        }
        any = true;
    }
    std::erase_if(workers_, [](const LocalWorker& w) { return w.pid < 0; });
    return any;
}

void Dispatcher::workerDied(LocalWorker& w) {
    int status = 0;
    waitpid(w.pid, &status, 0);
    forgetChild(w.pid);
    close(w.to);
    close(w.from);
    if (w.job) {
        const std::string why = WIFSIGNALED(status)
                                    ? std::string("worker killed by signal ") + std::to_string(WTERMSIG(status)) +
                                          " (" + strsignal(WTERMSIG(status)) + ")"
                                    : "worker exited with code " + std::to_string(WEXITSTATUS(status));
        const std::size_t i = *w.job;
        w.job.reset();
        finish(i, false, why, w.start, false);
    }
    w.pid = -1;
}

void Dispatcher::stopWorkers() {
    for (LocalWorker& w : workers_) {
        writeFrame(w.to, "-1");
        close(w.to);
        close(w.from);
        waitpid(w.pid, nullptr, 0);
        forgetChild(w.pid);
    }
    workers_.clear();
}

int Dispatcher::busyWorkers() const {
    int n = 0;
    for (const LocalWorker& w : workers_) n += w.job ? 1 : 0;
    return n;
}

}  // namespace vroc::harness::pool_detail
