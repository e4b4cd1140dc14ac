// SPDX-License-Identifier: MIT
#include "vroc/harness/run_pool.h"

#include <sched.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
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
volatile sig_atomic_t g_handling = 0;

void onInterrupt(int sig) {
    if (g_handling) _exit(128 + sig);
    g_handling = 1;
    for (auto& c : g_children) {
        const pid_t pid = c.load();
        if (pid > 0) kill(pid, SIGKILL);
    }
    const char* text = g_message[static_cast<std::size_t>(g_message_index.load())].data();
    [[maybe_unused]] const ssize_t n = write(STDERR_FILENO, text, std::strlen(text));
    _exit(128 + sig);
}

void publishMessage(const std::string& text) {
    const int next = 1 - g_message_index.load();
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
    }
    ~InterruptGuard() {
        for (std::size_t i = 0; i < kSignals.size(); ++i) sigaction(kSignals[i], &old_[i], nullptr);
    }
    static void restoreDefaults() {
        for (int s : kSignals) signal(s, SIG_DFL);
    }

private:
    static constexpr std::array<int, 3> kSignals{SIGINT, SIGTERM, SIGHUP};
    std::array<struct sigaction, 3> old_{};
};

std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
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
    Dispatcher(const PoolOptions& o, const std::string& plan_hash, const std::vector<PoolJob>& jobs, int local_slots)
        : o_(o), plan_hash_(plan_hash), jobs_(jobs), local_slots_(local_slots), results_(jobs.size()), failures_(jobs.size()) {}

    // Loads finished runs (resume); returns how many.
    int resume() {
        int n = 0;
        for (std::size_t i = 0; i < jobs_.size(); ++i)
            if (auto r = readRunFile(o_.runs_dir / (jobs_[i].id + ".json"), jobs_[i].id, plan_hash_)) {
                results_[i] = r->dump();
                ++n;
            }
        return n;
    }

    void execute() {
        for (std::size_t i = 0; i < jobs_.size(); ++i)
            if (!results_[i]) pending_.push_back(i);
        total_ = static_cast<int>(jobs_.size());
        done_ = total_ - static_cast<int>(pending_.size());
        started_ = Clock::now();
        InterruptGuard guard;
        updateStatus();
        const int ranks = mpi::size();
        std::vector<bool> rank_busy(static_cast<std::size_t>(ranks), false);
        int ranks_stopped = 0;
        if (ranks > 1 && o_.runs_dir.empty()) throw std::logic_error("RunPool: runs under MPI need a runs_dir");
        const bool in_process = (local_slots_ <= 1 || o_.runs_dir.empty()) && ranks == 1;
        while (outstanding() > 0 || (ranks > 1 && ranks_stopped < ranks - 1)) {
            bool progressed = false;
            if (in_process && !pending_.empty()) {
                const std::size_t i = takePending();
                const auto t0 = Clock::now();
                auto [ok, text] = runHere(jobs_[i]);
                finish(i, ok, std::move(text), t0);
                continue;
            }
            progressed |= reapLocal();
            while (!in_process && static_cast<int>(children_.size()) < local_slots_ && !pending_.empty()) {
                startLocal(takePending());
                progressed = true;
            }
            if (ranks > 1) progressed |= serveRanks(rank_busy, ranks_stopped);
            if (!progressed) std::this_thread::sleep_for(kPoll);
        }
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
    int outstanding() const { return static_cast<int>(pending_.size()) + static_cast<int>(children_.size()) + remote_running_; }

    std::size_t takePending() {
        const std::size_t i = pending_.front();
        pending_.erase(pending_.begin());
        return i;
    }

    void startLocal(std::size_t i) {
        std::fflush(nullptr);   // nothing buffered is written twice by the child
        const pid_t pid = fork();
        if (pid < 0) throw RunError(std::string("fork failed: ") + std::strerror(errno));
        if (pid == 0) {
            InterruptGuard::restoreDefaults();
            int code = 0;
            try {
                auto [ok, text] = runHere(jobs_[i]);
                if (ok) {
                    writeRunFile(o_.runs_dir, jobs_[i].id, plan_hash_, text);
                } else {
                    std::ofstream(o_.runs_dir / (jobs_[i].id + ".error")) << text;
                    code = 1;
                }
            } catch (...) {
                code = 2;
            }
            _exit(code);   // no destructors, no atexit handlers of the parent (MPI among them)
        }
        for (auto& c : g_children)
            if (c.load() == 0) { c.store(pid); break; }
        children_[pid] = {i, Clock::now()};
    }

    bool reapLocal() {
        bool any = false;
        for (;;) {
            int status = 0;
            const pid_t pid = waitpid(-1, &status, WNOHANG);
            if (pid <= 0) break;
            auto it = children_.find(pid);
            if (it == children_.end()) continue;
            for (auto& c : g_children)
                if (c.load() == pid) c.store(0);
            const auto [i, t0] = it->second;
            children_.erase(it);
            const std::filesystem::path result = o_.runs_dir / (jobs_[i].id + ".json");
            const std::filesystem::path error = o_.runs_dir / (jobs_[i].id + ".error");
            if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
                const std::optional<Json> r = readRunFile(result, jobs_[i].id, plan_hash_);
                if (r) finish(i, true, r->dump(), t0, false);
                else finish(i, false, "the worker exited without writing its result", t0, false);
            } else if (WIFEXITED(status)) {
                std::string why = std::filesystem::exists(error) ? readFile(error) : "worker exit code " + std::to_string(WEXITSTATUS(status));
                finish(i, false, why, t0, false);
            } else {
                finish(i, false, std::string("worker killed by signal ") + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")", t0, false);
            }
            any = true;
        }
        return any;
    }

    bool serveRanks(std::vector<bool>& busy, int& stopped) {
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
            finish(i, ok, std::move(body), remote_start_[i]);
            busy[static_cast<std::size_t>(from)] = false;
            assign(from, busy, stopped);
            any = true;
        }
        while (mpi::receiveText(kTagReady, from, text)) {
            assign(from, busy, stopped);
            any = true;
        }
        return any;
    }

    void assign(int rank, std::vector<bool>& busy, int& stopped) {
        if (pending_.empty()) {
            mpi::sendText(rank, kTagAssign, "-1");
            ++stopped;
            return;
        }
        const std::size_t i = takePending();
        remote_start_[i] = Clock::now();
        ++remote_running_;
        busy[static_cast<std::size_t>(rank)] = true;
        mpi::sendText(rank, kTagAssign, std::to_string(i));
    }

    void finish(std::size_t i, bool ok, std::string text, Clock::time_point t0, bool write = true) {
        if (ok) {
            if (write) {   // in-process runs: normalised through the parser, then written
                text = Json::parse(text).dump();
                writeRunFile(o_.runs_dir, jobs_[i].id, plan_hash_, text);
            }
            results_[i] = std::move(text);
            ++done_;
            std::error_code ec;
            if (!o_.runs_dir.empty()) std::filesystem::remove(o_.runs_dir / (jobs_[i].id + ".error"), ec);
        } else {
            failures_[i] = std::move(text);
            ++failed_;
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
        recording::AtomicFile f(o_.runs_dir / "status.json");
        f.write(status.dump(2) + "\n");
        f.commit();
        publishMessage("\n" + o_.command + ": interrupted: " + std::to_string(done_) + " of " + std::to_string(total_) +
                       " runs finished, " + std::to_string(n_missing) + " did not: " + names + ". The finished runs are kept in " +
                       o_.runs_dir.string() + " (status.json lists the rest); rerun the same command with --resume to finish only what is missing.\n");
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
    std::vector<std::optional<std::string>> results_;
    std::vector<std::optional<std::string>> failures_;
    std::vector<std::size_t> pending_;
    std::map<pid_t, std::pair<std::size_t, Clock::time_point>> children_;
    std::map<std::size_t, Clock::time_point> remote_start_;
    int remote_running_ = 0;
    int total_ = 0, done_ = 0, failed_ = 0, executed_ = 0;
    double run_seconds_ = 0;
    Clock::time_point started_;
};

// A worker rank's side of a phase: ask, run, answer, until rank 0 says there is no more.
void serveAsWorker(const std::vector<PoolJob>& jobs) {
    mpi::sendText(0, kTagReady, "");
    for (;;) {
        const long i = std::stol(mpi::waitText(0, kTagAssign));
        if (i < 0) break;
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

std::vector<Json> RunPool::run(const std::vector<PoolJob>& jobs) {
    for (std::size_t i = 0; i < jobs.size(); ++i)
        for (std::size_t k = 0; k < i; ++k)
            if (jobs[i].id == jobs[k].id) throw std::logic_error("RunPool: job id '" + jobs[i].id + "' appears twice");
    std::string outcome;
    if (mpi::isRoot()) {
        Dispatcher d(options_, plan_hash_, jobs, options_.jobs);
        if (options_.resume && !options_.runs_dir.empty()) resumed_ += d.resume();
        d.execute();
        outcome = d.outcome();
    } else {
        serveAsWorker(jobs);
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

Json RunPool::executionJson() const {
    return {{"jobs", options_.jobs}, {"ranks", mpi::size()}, {"mpi_library", mpi::libraryVersion()}, {"runs", runs_}, {"resumed", resumed_}};
}

}  // namespace vroc::harness
