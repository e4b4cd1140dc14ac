// SPDX-License-Identifier: MIT
#include "vroc/harness/run_pool.h"

#include <fcntl.h>
#include <poll.h>
#include <sched.h>
#include <time.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <optional>
#include <sstream>
#include <thread>

#include "vroc/core/errors.h"
#include "vroc/core/recording/atomic_output.h"
#include "vroc/core/state_hash.h"
#include "vroc/harness/mpi_world.h"

namespace vroc::harness {
namespace {

constexpr const char* kRunFormat = "vroc-run-result/1";
constexpr int kMaxLocalWorkers = 256;
constexpr auto kPoll = std::chrono::microseconds(500);
constexpr int kExitInterrupted = 3;   // docs/cli.md: 3 = failure while running, interruption included

// MPI message tags of the hand-out protocol (rank 0 <-> worker ranks).
constexpr int kTagReady = 11;      // worker -> 0: idle, send me a job
constexpr int kTagAssign = 12;     // 0 -> worker: job index, or -1: no more in this phase
constexpr int kTagResult = 13;     // worker -> 0: "<index>\n<ok|fail>\n<result JSON | reason>"
constexpr int kTagPhaseEnd = 14;   // 0 -> worker: every result is in; the broadcast follows

using Clock = std::chrono::steady_clock;

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

// Installs the interrupt handler for the life of a phase, restoring the previous ones after.
class InterruptGuard {
public:
    InterruptGuard() {
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
    ~InterruptGuard() {
        for (std::size_t i = 0; i < kSignals.size(); ++i) sigaction(kSignals[i], &old_[i], nullptr);
        sigaction(SIGPIPE, &old_pipe_, nullptr);
    }
    static void restoreDefaults() {
        for (int s : kSignals) signal(s, SIG_DFL);
        signal(SIGPIPE, SIG_DFL);
    }

private:
    static constexpr std::array<int, 3> kSignals{SIGINT, SIGTERM, SIGHUP};
    std::array<struct sigaction, 3> old_{};
    struct sigaction old_pipe_ {};
};

std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// Length-prefixed messages over a pipe between the dispatcher and its local workers.
bool writeAll(int fd, const char* data, std::size_t n) {
    while (n > 0) {
        const ssize_t k = write(fd, data, n);
        if (k < 0 && errno == EINTR) continue;
        if (k <= 0) return false;
        data += k;
        n -= static_cast<std::size_t>(k);
    }
    return true;
}

bool readAll(int fd, char* data, std::size_t n) {
    while (n > 0) {
        const ssize_t k = read(fd, data, n);
        if (k < 0 && errno == EINTR) continue;
        if (k <= 0) return false;
        data += k;
        n -= static_cast<std::size_t>(k);
    }
    return true;
}

bool writeFrame(int fd, const std::string& text) {
    const std::uint64_t n = text.size();
    return writeAll(fd, reinterpret_cast<const char*>(&n), sizeof n) && writeAll(fd, text.data(), text.size());
}

bool readFrame(int fd, std::string& text) {
    std::uint64_t n = 0;
    if (!readAll(fd, reinterpret_cast<char*>(&n), sizeof n)) return false;
    text.assign(n, '\0');
    return readAll(fd, text.data(), n);
}

std::string fileText(const std::string& job, const std::string& plan_hash, const std::string& result_text) {
    // Written by hand around the result's own text so the result is never re-serialised.
    return std::string("{\"format\":\"") + kRunFormat + "\",\"job\":" + Json(job).dump() + ",\"plan_hash\":\"" + plan_hash +
           "\",\"result\":" + result_text + "}\n";
}

void writeRunFile(const std::filesystem::path& dir, const std::string& job, const std::string& plan_hash, const std::string& result_text) {
    if (dir.empty()) return;
    recording::AtomicFile f(dir / (job + ".json"));
    f.write(fileText(job, plan_hash, result_text));
    f.commit();
}

// The result of a finished run on disk, if it belongs to this plan; throws InputError if it
// belongs to another plan (the folder holds some other command's runs).
std::optional<Json> readRunFile(const std::filesystem::path& path, const std::string& job, const std::string& plan_hash) {
    if (!std::filesystem::exists(path)) return std::nullopt;
    Json doc = Json::parse(readFile(path), nullptr, false);
    if (doc.is_discarded() || !doc.is_object() || doc.value("format", "") != kRunFormat || doc.value("job", "") != job)
        throw InputError(path.string() + ": not a finished run of job '" + job + "' (expected " + kRunFormat + "); remove it or use a new --out");
    if (doc.value("plan_hash", "") != plan_hash)
        throw InputError(path.string() + ": written by a different plan (hash " + doc.value("plan_hash", "?") + ", this command's is " +
                         plan_hash + "): --resume needs the same scene, options and build; use a new --out or drop --resume");
    return std::move(doc["result"]);
}

double threadCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

std::string errorText(const std::exception_ptr& e) {
    try {
        std::rethrow_exception(e);
    } catch (const std::exception& x) {
        return x.what();
    } catch (...) {
        return "unknown exception";
    }
}

// Runs a job here and returns (ok, result text or reason).
std::pair<bool, std::string> runHere(const PoolJob& job) {
    try {
        return {true, job.run().dump()};
    } catch (...) {
        return {false, errorText(std::current_exception())};
    }
}

// One phase of runs on rank 0: local forked workers (or this process) plus the worker ranks.
class Dispatcher {
public:
    Dispatcher(const PoolOptions& o, const std::string& plan_hash, const std::vector<PoolJob>& jobs, int local_slots,
               const DependencyHook& on_dependency)
        : o_(o), plan_hash_(plan_hash), jobs_(jobs), local_slots_(local_slots), on_dependency_(on_dependency),
          results_(jobs.size()), failures_(jobs.size()), is_dependency_(jobs.size(), false),
          sent_(static_cast<std::size_t>(mpi::size())) {
        for (const PoolJob& j : jobs)
            for (std::size_t a : j.after) {
                if (a >= jobs.size()) throw std::logic_error("RunPool: job '" + j.id + "' depends on a job index out of range");
                is_dependency_[a] = true;
            }
    }

    // Loads finished runs (resume); returns how many.
    int resume() {
        int n = 0;
        for (std::size_t i = 0; i < jobs_.size(); ++i)
            if (auto r = readRunFile(o_.runs_dir / (jobs_[i].id + ".json"), jobs_[i].id, plan_hash_)) {
                results_[i] = r->dump();
                if (is_dependency_[i] && on_dependency_) on_dependency_(i, Json::parse(*results_[i]));
                ++n;
            }
        return n;
    }

    void execute() {
        for (std::size_t i = 0; i < jobs_.size(); ++i)
            if (!results_[i]) pending_.push_back(i);
        // Longest first (stable: equal estimates keep job order), so the tail is short jobs.
        std::stable_sort(pending_.begin(), pending_.end(), [&](std::size_t a, std::size_t b) { return jobs_[a].cost > jobs_[b].cost; });
        total_ = static_cast<int>(jobs_.size());
        done_ = total_ - static_cast<int>(pending_.size());
        started_ = Clock::now();
        const double cpu_start = threadCpuSeconds();
        InterruptGuard guard;
        updateStatus();
        const int ranks = mpi::size();
        int ranks_stopped = 0;
        if (ranks > 1 && o_.runs_dir.empty()) throw std::logic_error("RunPool: runs under MPI need a runs_dir");
        const bool in_process = local_slots_ <= 1 && ranks == 1;
        while (outstanding() > 0 || (ranks > 1 && ranks_stopped < ranks - 1)) {
            bool progressed = false;
            if (in_process) {
                const std::optional<std::size_t> i = takeReady();
                if (!i) throw std::logic_error("RunPool: no job is ready and none is running (a dependency cycle?)");
                const auto t0 = Clock::now();
                auto [ok, text] = runHere(jobs_[*i]);
                finish(*i, ok, std::move(text), t0);
                continue;
            }
            progressed |= collectLocal(0);
            for (;;) {   // idle local workers (spawned as needed, up to --jobs) take ready jobs
                LocalWorker* idle = nullptr;
                for (LocalWorker& w : workers_) if (!w.job && w.pid > 0) { idle = &w; break; }
                if (!idle && static_cast<int>(workers_.size()) >= local_slots_) break;
                const std::optional<std::size_t> i = takeReady();
                if (!i) break;
                if (!idle) {
                    spawnWorker();
                    idle = &workers_.back();
                }
                assignLocal(*idle, *i);
                progressed = true;
            }
            std::erase_if(workers_, [](const LocalWorker& w) { return w.pid < 0; });
            if (ranks > 1) progressed |= serveRanks(ranks_stopped);
            // Alone, sleep in the kernel until a worker answers; with ranks, poll their messages too.
            if (!progressed && ranks == 1 && busyWorkers() > 0) collectLocal(-1);
            else if (!progressed && !collectLocal(1) && busyWorkers() == 0) std::this_thread::sleep_for(kPoll);
        }
        stopWorkers();
        if (!in_process) dispatch_s_ = threadCpuSeconds() - cpu_start;
        if (ranks > 1)
            for (int r = 1; r < ranks; ++r) mpi::sendText(r, kTagPhaseEnd, "");
    }

    // The phase's outcome as the text every rank receives: {"results": [...]} or {"error": "..."}.
    std::string outcome() const {
        std::string failed;
        int n = 0;
        for (std::size_t i = 0; i < jobs_.size(); ++i)
            if (failures_[i]) {
                if (n++ < 10) failed += (failed.empty() ? "" : "; ") + jobs_[i].id + ": " + *failures_[i];
            }
        if (n > 0) {
            Json e = {{"error", std::to_string(n) + " of " + std::to_string(jobs_.size()) + " runs failed (" + failed +
                                    (n > 10 ? "; ..." : "") + "). The finished runs are kept in " + o_.runs_dir.string() +
                                    "; rerun the same command with --resume to run only the missing ones"}};
            return e.dump();
        }
        std::string out = "{\"results\":[";
        for (std::size_t i = 0; i < results_.size(); ++i) out += (i ? "," : "") + *results_[i];
        return out + "]}";
    }

private:
    int outstanding() const { return static_cast<int>(pending_.size()) + busyWorkers() + remote_running_; }

    // The costliest pending job whose dependencies have all finished.
    std::optional<std::size_t> takeReady() {
        for (auto it = pending_.begin(); it != pending_.end(); ++it) {
            const auto& after = jobs_[*it].after;
            if (std::all_of(after.begin(), after.end(), [&](std::size_t a) { return results_[a].has_value(); })) {
                const std::size_t i = *it;
                pending_.erase(it);
                return i;
            }
        }
        return std::nullopt;
    }

    // Jobs that can never run because a job they depend on failed fail too, named.
    void failDependents() {
        for (bool changed = true; changed;) {
            changed = false;
            for (auto it = pending_.begin(); it != pending_.end();) {
                std::optional<std::size_t> broken;
                for (std::size_t a : jobs_[*it].after)
                    if (failures_[a]) broken = a;
                if (!broken) { ++it; continue; }
                failures_[*it] = "not run: it needs " + jobs_[*broken].id + ", which failed";
                ++failed_;
                it = pending_.erase(it);
                changed = true;
            }
        }
    }

    // A local worker: a process forked once per phase that runs jobs it is sent over a pipe, so a
    // phase pays one fork per worker, not per run. It writes each result file itself and answers
    // "ok" or "fail\n<reason>"; a worker that dies costs its current run and is replaced.
    struct LocalWorker {
        pid_t pid = -1;
        int to = -1, from = -1;                  ///< command pipe (write end), answer pipe (read end)
        std::optional<std::size_t> job;
        Clock::time_point start;
        std::set<std::size_t> sent;              ///< dependency results it has been sent
    };

    void spawnWorker() {
        int down[2], up[2];
        if (pipe(down) != 0 || pipe(up) != 0) throw RunError(std::string("pipe failed: ") + std::strerror(errno));
        std::fflush(nullptr);   // nothing buffered is written twice by the child
        const pid_t pid = fork();
        if (pid < 0) throw RunError(std::string("fork failed: ") + std::strerror(errno));
        if (pid == 0) {
            InterruptGuard::restoreDefaults();
            close(down[1]);
            close(up[0]);
            for (const LocalWorker& w : workers_) { close(w.to); close(w.from); }
            serveAsLocalWorker(down[0], up[1]);
            _exit(0);   // no destructors, no atexit handlers of the parent (MPI among them)
        }
        close(down[0]);
        close(up[1]);
        for (auto& c : g_children)
            if (c.load() == 0) { c.store(pid); break; }
        workers_.push_back({pid, down[1], up[0], std::nullopt, {}, {}});
    }

    void serveAsLocalWorker(int in, int out) {
        std::string command;
        while (readFrame(in, command)) {
            const long i = std::stol(command);
            if (i < 0) return;
            const std::size_t nl = command.find('\n');
            if (nl != std::string::npos && on_dependency_)
                for (const Json& d : Json::parse(command.substr(nl + 1))) on_dependency_(d[0].get<std::size_t>(), d[1]);
            auto [ok, text] = runHere(jobs_[static_cast<std::size_t>(i)]);
            if (ok && o_.runs_dir.empty()) {   // nothing kept on disk: the result travels over the pipe
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

    void assignLocal(LocalWorker& w, std::size_t i) {
        std::string deps = "[";
        for (std::size_t a : jobs_[i].after)
            if (w.sent.insert(a).second) deps += (deps.size() > 1 ? ",[" : "[") + std::to_string(a) + "," + *results_[a] + "]";
        w.job = i;
        w.start = Clock::now();
        if (!writeFrame(w.to, std::to_string(i) + "\n" + deps + "]")) workerDied(w);
    }

    // Waits up to `timeout_ms` (-1: until one answers) for answers of busy workers.
    bool collectLocal(int timeout_ms) {
        std::vector<pollfd> fds;
        for (const LocalWorker& w : workers_)
            if (w.job) fds.push_back({w.from, POLLIN, 0});
        if (fds.empty()) return false;
        if (poll(fds.data(), fds.size(), timeout_ms) <= 0) return false;
        bool any = false;
        for (LocalWorker& w : workers_) {
            if (!w.job) continue;
            pollfd* f = nullptr;
            for (pollfd& p : fds) if (p.fd == w.from) f = &p;
            if (!f || !(f->revents & (POLLIN | POLLHUP | POLLERR))) continue;
            std::string answer;
            if (!readFrame(w.from, answer)) { workerDied(w); any = true; continue; }
            const std::size_t i = *w.job;
            w.job.reset();
            if (answer.rfind("ok\n", 0) == 0) {   // no runs_dir: the result itself, normalised as a file's is
                finish(i, true, Json::parse(std::string_view(answer).substr(3)).dump(), w.start, false);
            } else if (answer == "ok") {
                const std::optional<Json> r = readRunFile(o_.runs_dir / (jobs_[i].id + ".json"), jobs_[i].id, plan_hash_);
                if (r) finish(i, true, r->dump(), w.start, false);
                else finish(i, false, "the worker answered without writing its result", w.start, false);
            } else {
                finish(i, false, answer.substr(answer.find('\n') + 1), w.start, false);
            }
            any = true;
        }
        std::erase_if(workers_, [](const LocalWorker& w) { return w.pid < 0; });
        return any;
    }

    // A worker that stopped answering: its run fails, named with the signal that ended it.
    void workerDied(LocalWorker& w) {
        int status = 0;
        waitpid(w.pid, &status, 0);
        for (auto& c : g_children)
            if (c.load() == w.pid) c.store(0);
        close(w.to);
        close(w.from);
        if (w.job) {
            const std::string why = WIFSIGNALED(status) ? std::string("worker killed by signal ") + std::to_string(WTERMSIG(status)) + " (" +
                                                              strsignal(WTERMSIG(status)) + ")"
                                                        : "worker exited with code " + std::to_string(WEXITSTATUS(status));
            const std::size_t i = *w.job;
            w.job.reset();
            finish(i, false, why, w.start, false);
        }
        w.pid = -1;
    }

    void stopWorkers() {
        for (LocalWorker& w : workers_) {
            writeFrame(w.to, "-1");
            close(w.to);
            close(w.from);
            waitpid(w.pid, nullptr, 0);
            for (auto& c : g_children)
                if (c.load() == w.pid) c.store(0);
        }
        workers_.clear();
    }

    int busyWorkers() const {
        int n = 0;
        for (const LocalWorker& w : workers_) n += w.job ? 1 : 0;
        return n;
    }

    bool serveRanks(int& stopped) {
        bool any = false;
        int from = 0;
        std::string text;
        while (mpi::receiveText(kTagResult, from, text)) {
            const std::size_t nl1 = text.find('\n'), nl2 = text.find('\n', nl1 + 1);
            const std::size_t i = std::stoul(text.substr(0, nl1));
            const bool ok = text.compare(nl1 + 1, nl2 - nl1 - 1, "ok") == 0;
            std::string body = text.substr(nl2 + 1);
            if (ok) {
                // Normalised through the parser, exactly as a local worker's file is.
                body = Json::parse(body).dump();
                writeRunFile(o_.runs_dir, jobs_[i].id, plan_hash_, body);
            }
            --remote_running_;
            finish(i, ok, std::move(body), remote_start_[i], false);
            idle_ranks_.push_back(from);
            any = true;
        }
        while (mpi::receiveText(kTagReady, from, text)) {
            idle_ranks_.push_back(from);
            any = true;
        }
        // Idle ranks get a ready job, or -1 once nothing is left to hand out; a rank waits while
        // the jobs left still wait for their dependencies.
        while (!idle_ranks_.empty()) {
            const int rank = idle_ranks_.front();
            if (pending_.empty()) {
                mpi::sendText(rank, kTagAssign, "-1");
                ++stopped;
            } else if (const std::optional<std::size_t> i = takeReady()) {
                assign(rank, *i);
            } else {
                break;
            }
            idle_ranks_.erase(idle_ranks_.begin());
            any = true;
        }
        return any;
    }

    // "<index>\n[[dependency index, result], ...]": the results of the job's dependencies that
    // rank has not been sent yet, so it can rebuild what the job reads.
    void assign(int rank, std::size_t i) {
        std::string deps = "[";
        auto& sent = sent_[static_cast<std::size_t>(rank)];
        for (std::size_t a : jobs_[i].after)
            if (sent.insert(a).second) deps += (deps.size() > 1 ? ",[" : "[") + std::to_string(a) + "," + *results_[a] + "]";
        remote_start_[i] = Clock::now();
        ++remote_running_;
        mpi::sendText(rank, kTagAssign, std::to_string(i) + "\n" + deps + "]");
    }

    void finish(std::size_t i, bool ok, std::string text, Clock::time_point t0, bool write = true) {
        if (ok) {
            if (write) {   // in-process runs: normalised through the parser, then written
                text = Json::parse(text).dump();
                writeRunFile(o_.runs_dir, jobs_[i].id, plan_hash_, text);
            }
            results_[i] = std::move(text);
            if (is_dependency_[i] && on_dependency_) on_dependency_(i, Json::parse(*results_[i]));
            ++done_;
            std::error_code ec;
            if (!o_.runs_dir.empty()) std::filesystem::remove(o_.runs_dir / (jobs_[i].id + ".error"), ec);
        } else {
            failures_[i] = std::move(text);
            ++failed_;
            failDependents();
        }
        run_seconds_ += std::chrono::duration<double>(Clock::now() - t0).count();
        ++executed_;
        updateStatus();
    }

    // status.json, the interrupt message, and the progress callback, after every finished run.
    void updateStatus() {
        Json missing = Json::array();
        std::string names;
        int listed = 0, n_missing = 0;
        for (std::size_t i = 0; i < jobs_.size(); ++i) {
            if (results_[i]) continue;
            missing.push_back(jobs_[i].id);
            ++n_missing;
            if (listed < 12) names += (listed++ ? ", " : "") + jobs_[i].id;
        }
        if (n_missing > listed) names += ", and " + std::to_string(n_missing - listed) + " more";
        if (o_.runs_dir.empty()) return reportProgress();
        const Json status = {{"command", o_.command}, {"plan_hash", plan_hash_}, {"runs", jobs_.size()}, {"finished", done_},
                             {"failed", failed_}, {"not_finished", missing}, {"complete", n_missing == 0}};
        const std::string status_text = status.dump(2) + "\n";
        // Synced to disk at most twice a second and at the end; an interrupt writes the latest.
        const auto now = Clock::now();
        if (n_missing == 0 || done_ + failed_ == total_ || now - last_status_write_ > std::chrono::milliseconds(500)) {
            recording::AtomicFile f(o_.runs_dir / "status.json");
            f.write(status_text);
            f.commit();
            last_status_write_ = now;
        }
        // One line in the CLI's error form; after a progress bar, on a line of its own.
        const std::string command = o_.command.rfind("vroc ", 0) == 0 ? o_.command.substr(5) : o_.command;
        publishMessage(std::string(isatty(STDERR_FILENO) ? "\n" : "") + "vroc: error: " + command + " interrupted: " + std::to_string(done_) + " of " + std::to_string(total_) +
                       " runs finished, " + std::to_string(n_missing) + " did not: " + names + ". The finished runs are kept in " +
                       o_.runs_dir.string() + " (status.json lists the rest); rerun the same command with --resume to finish only what is missing.\n",
                       o_.runs_dir / "status.json", status_text);
        reportProgress();
    }

    void reportProgress() {
        if (o_.progress) {
            PoolProgress p{total_, done_, failed_, -1};
            const int slots = std::max(1, local_slots_) + std::max(0, mpi::size() - 1);
            if (executed_ > 0) p.seconds_left = run_seconds_ / executed_ * (total_ - done_ - failed_) / slots;
            o_.progress(p);
        }
    }

    const PoolOptions& o_;
    const std::string& plan_hash_;
    const std::vector<PoolJob>& jobs_;
    int local_slots_;
    const DependencyHook& on_dependency_;
    std::vector<std::optional<std::string>> results_;
    std::vector<std::optional<std::string>> failures_;
    std::vector<bool> is_dependency_;
    std::vector<std::set<std::size_t>> sent_;   ///< per rank: dependency results it has been sent
    std::vector<int> idle_ranks_;
    std::vector<std::size_t> pending_;
    std::vector<LocalWorker> workers_;
    std::map<std::size_t, Clock::time_point> remote_start_;
    int remote_running_ = 0;
    int total_ = 0, done_ = 0, failed_ = 0, executed_ = 0;
    double run_seconds_ = 0;
    Clock::time_point last_status_write_{};
    double dispatch_s_ = 0;    ///< [s] CPU time of the dispatcher's own work: hand-out, result files, status, polling

public:
    double dispatchSeconds() const { return dispatch_s_; }

private:
    Clock::time_point started_;
};

// A worker rank's side of a phase: ask, run, answer, until rank 0 says there is no more.
void serveAsWorker(const std::vector<PoolJob>& jobs, const DependencyHook& on_dependency) {
    mpi::sendText(0, kTagReady, "");
    for (;;) {
        const std::string assignment = mpi::waitText(0, kTagAssign);
        const long i = std::stol(assignment);
        if (i < 0) break;
        for (const Json& d : Json::parse(assignment.substr(assignment.find('\n') + 1)))
            if (on_dependency) on_dependency(d[0].get<std::size_t>(), d[1]);
        auto [ok, text] = runHere(jobs.at(static_cast<std::size_t>(i)));
        mpi::sendText(0, kTagResult, std::to_string(i) + "\n" + (ok ? "ok" : "fail") + "\n" + text);
    }
    mpi::waitText(0, kTagPhaseEnd);
}

std::string planHash(const Json& plan) {
    const std::string text = plan.dump();
    std::uint64_t h = 1469598103934665603ull;   // FNV-1a 64
    for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
    return hashToHex(h);
}

}  // namespace

std::string poolJobId(const std::string& text) {
    std::string out;
    for (char c : text) out += (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '=' || c == '-') ? c : '_';
    return out;
}

int defaultJobs() {
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
    return std::max(1u, std::thread::hardware_concurrency());
}

RunPool::RunPool(PoolOptions options) : options_(std::move(options)), plan_hash_(planHash(options_.plan)) {
    if (options_.jobs < 0) throw InputError("--jobs: expected a positive number of runs at once (0 or absent: every core)");
    if (options_.jobs == 0) options_.jobs = mpi::size() > 1 ? 1 : defaultJobs();
    options_.jobs = std::min(options_.jobs, kMaxLocalWorkers);
    if (!mpi::isRoot() || options_.runs_dir.empty()) return;
    std::error_code ec;
    if (!options_.resume) std::filesystem::remove_all(options_.runs_dir, ec);   // the folder's earlier runs belong to no one now
    std::filesystem::create_directories(options_.runs_dir, ec);
    if (!std::filesystem::is_directory(options_.runs_dir))
        throw InputError(options_.runs_dir.string() + ": cannot create the folder for finished runs (" + ec.message() + ")");
    writeDocument(options_.plan, options_.runs_dir / "plan.json");
}

RunPool RunPool::inProcess() {
    PoolOptions o;
    o.jobs = 1;
    return RunPool(std::move(o));
}

std::vector<Json> RunPool::run(const std::vector<PoolJob>& jobs, const DependencyHook& on_dependency) {
    for (std::size_t i = 0; i < jobs.size(); ++i)
        for (std::size_t k = 0; k < i; ++k)
            if (jobs[i].id == jobs[k].id) throw std::logic_error("RunPool: job id '" + jobs[i].id + "' appears twice");
    std::string outcome;
    if (mpi::isRoot()) {
        Dispatcher d(options_, plan_hash_, jobs, options_.jobs, on_dependency);
        if (options_.resume && !options_.runs_dir.empty()) resumed_ += d.resume();
        d.execute();
        dispatch_s_ += d.dispatchSeconds();
        outcome = d.outcome();
    } else {
        serveAsWorker(jobs, on_dependency);
    }
    runs_ += static_cast<int>(jobs.size());
    mpi::broadcastText(outcome);
    Json doc = Json::parse(outcome);
    if (doc.contains("error")) throw RunError(doc["error"].get<std::string>());
    std::vector<Json> out;
    out.reserve(jobs.size());
    for (Json& r : doc["results"]) out.push_back(std::move(r));
    return out;
}

PoolExecution RunPool::execution() const {
    return {options_.jobs, mpi::size(), mpi::libraryVersion(), runs_, resumed_, dispatch_s_};
}

Json executionJson(const PoolExecution& e) {
    return {{"jobs", e.jobs}, {"ranks", e.ranks}, {"mpi_library", e.mpi_library}, {"runs", e.runs}, {"resumed", e.resumed},
            {"dispatch_s", e.dispatch_s}};
}

}  // namespace vroc::harness
