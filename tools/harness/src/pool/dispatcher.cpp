// SPDX-License-Identifier: MIT
#include "dispatcher.h"

#include <algorithm>
#include <stdexcept>
#include <thread>
#include <time.h>
#include <unistd.h>

#include "interrupt.h"
#include "run_files.h"
#include "vroc/core/recording/atomic_output.h"
#include "vroc/harness/pool/mpi_world.h"

namespace vroc::harness::pool_detail {
namespace {

constexpr auto kPoll = std::chrono::microseconds(500);

double threadCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace

std::string errorText(const std::exception_ptr& e) {
    try {
        std::rethrow_exception(e);
    } catch (const std::exception& x) {
        return x.what();
    } catch (...) {
        return "unknown exception";
    }
}

std::pair<bool, std::string> runHere(const PoolJob& job) {
    try {
        return {true, job.run().dump()};
    } catch (...) {
        return {false, errorText(std::current_exception())};
    }
}

Dispatcher::Dispatcher(const PoolOptions& o, const std::string& plan_hash, const std::vector<PoolJob>& jobs,
                       int local_slots, const DependencyHook& on_dependency)
    : o_(o),
      plan_hash_(plan_hash),
      jobs_(jobs),
      local_slots_(local_slots),
      on_dependency_(on_dependency),
      results_(jobs.size()),
      failures_(jobs.size()),
      is_dependency_(jobs.size(), false),
      sent_(static_cast<std::size_t>(mpi::size())) {
    for (const PoolJob& j : jobs)
        for (std::size_t a : j.after) {
            if (a >= jobs.size())
                throw std::logic_error("RunPool: job '" + j.id + "' depends on a job index out of range");
            is_dependency_[a] = true;
        }
}

int Dispatcher::resume() {
    int n = 0;
    for (std::size_t i = 0; i < jobs_.size(); ++i)
        if (auto r = readRunFile(o_.runs_dir / (jobs_[i].id + ".json"), jobs_[i].id, plan_hash_)) {
            results_[i] = r->dump();
            if (is_dependency_[i] && on_dependency_) on_dependency_(i, Json::parse(*results_[i]));
            ++n;
        }
    return n;
}

void Dispatcher::execute() {
    for (std::size_t i = 0; i < jobs_.size(); ++i)
        if (!results_[i]) pending_.push_back(i);
    // Longest first (stable: equal estimates keep job order), so the tail is short jobs.
    std::stable_sort(pending_.begin(), pending_.end(),
                     [&](std::size_t a, std::size_t b) { return jobs_[a].cost > jobs_[b].cost; });
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
        for (;;) {  // idle local workers (spawned as needed, up to --jobs) take ready jobs
            LocalWorker* idle = nullptr;
            for (LocalWorker& w : workers_)
                if (!w.job && w.pid > 0) {
                    idle = &w;
                    break;
                }
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
        if (!progressed && ranks == 1 && busyWorkers() > 0)
            collectLocal(-1);
        else if (!progressed && !collectLocal(1) && busyWorkers() == 0)
            std::this_thread::sleep_for(kPoll);
    }
    stopWorkers();
    if (!in_process) dispatch_s_ = threadCpuSeconds() - cpu_start;
    if (ranks > 1) endPhaseOnRanks();
}

std::string Dispatcher::outcome() const {
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

std::optional<std::size_t> Dispatcher::takeReady() {
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

void Dispatcher::failDependents() {
    for (bool changed = true; changed;) {
        changed = false;
        for (auto it = pending_.begin(); it != pending_.end();) {
            std::optional<std::size_t> broken;
            for (std::size_t a : jobs_[*it].after)
                if (failures_[a]) broken = a;
            if (!broken) {
                ++it;
                continue;
            }
            failures_[*it] = "not run: it needs " + jobs_[*broken].id + ", which failed";
            ++failed_;
            it = pending_.erase(it);
            changed = true;
        }
    }
}

void Dispatcher::finish(std::size_t i, bool ok, std::string text, Clock::time_point t0, bool write) {
    if (ok) {
        if (write) {  // in-process runs: normalised through the parser, then written
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

void Dispatcher::updateStatus() {
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
    const Json status = {{"command", o_.command},     {"plan_hash", plan_hash_}, {"runs", jobs_.size()},
                         {"finished", done_},         {"failed", failed_},       {"not_finished", missing},
                         {"complete", n_missing == 0}};
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
    publishMessage(
        std::string(isatty(STDERR_FILENO) ? "\n" : "") + "vroc: error: " + command + " interrupted: " +
            std::to_string(done_) + " of " + std::to_string(total_) + " runs finished, " + std::to_string(n_missing) +
            " did not: " + names + ". The finished runs are kept in " + o_.runs_dir.string() +
            " (status.json lists the rest); rerun the same command with --resume to finish only what is missing.\n",
        o_.runs_dir / "status.json", status_text);
    reportProgress();
}

void Dispatcher::reportProgress() {
    if (o_.progress) {
        PoolProgress p{total_, done_, failed_, -1};
        const int slots = std::max(1, local_slots_) + std::max(0, mpi::size() - 1);
        if (executed_ > 0) p.seconds_left = run_seconds_ / executed_ * (total_ - done_ - failed_) / slots;
        o_.progress(p);
    }
}

}  // namespace vroc::harness::pool_detail
