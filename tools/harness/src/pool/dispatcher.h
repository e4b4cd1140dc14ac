// SPDX-License-Identifier: MIT
// One phase of a RunPool's runs on rank 0 (run_pool.h): which job is ready, who runs it, what
// finished, what failed, status.json and the interrupt message. Its parts live in one file each:
//   dispatcher.cpp     the phase: hand-out order, finishing a run, status, the outcome;
//   local_workers.cpp  worker processes forked once per phase and fed jobs over pipes;
//   rank_hand_out.cpp  the worker ranks under `mpirun`: jobs out one at a time, results back.
#pragma once

#include <chrono>
#include <cstddef>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <sys/types.h>
#include <utility>
#include <vector>

#include "vroc/harness/pool/run_pool.h"

namespace vroc::harness::pool_detail {

using Clock = std::chrono::steady_clock;

/// Runs a job in this process: (true, its result's JSON text) or (false, the reason it failed).
std::pair<bool, std::string> runHere(const PoolJob& job);
/// The message of an exception in flight.
std::string errorText(const std::exception_ptr& e);

/// A worker rank's side of a phase (rank_hand_out.cpp): ask, run, answer, until rank 0 says there is no more.
void serveAsWorker(const std::vector<PoolJob>& jobs, const DependencyHook& on_dependency);

class Dispatcher {
public:
    Dispatcher(const PoolOptions& o, const std::string& plan_hash, const std::vector<PoolJob>& jobs, int local_slots,
               const DependencyHook& on_dependency);

    /// Loads finished runs (resume); returns how many.
    int resume();
    /// Runs every job not yet finished, on local workers (or in this process) and the worker ranks.
    void execute();
    /// The phase's outcome as the text every rank receives: {"results": [...]} or {"error": "..."}.
    std::string outcome() const;
    double dispatchSeconds() const { return dispatch_s_; }

private:
    // A local worker: a process forked once per phase that runs jobs it is sent over a pipe, so a
    // phase pays one fork per worker, not per run. It writes each result file itself and answers
    // "ok" or "fail\n<reason>"; a worker that dies costs its current run and is replaced.
    struct LocalWorker {
        pid_t pid = -1;
        int to = -1, from = -1;  ///< command pipe (write end), answer pipe (read end)
        std::optional<std::size_t> job;
        Clock::time_point start;
        std::set<std::size_t> sent;  ///< dependency results it has been sent
    };

    // ---- the phase (dispatcher.cpp)
    int outstanding() const { return static_cast<int>(pending_.size()) + busyWorkers() + remote_running_; }
    /// The costliest pending job whose dependencies have all finished.
    std::optional<std::size_t> takeReady();
    /// Jobs that can never run because a job they depend on failed fail too, named.
    void failDependents();
    void finish(std::size_t i, bool ok, std::string text, Clock::time_point t0, bool write = true);
    /// status.json, the interrupt message, and the progress callback, after every finished run.
    void updateStatus();
    void reportProgress();

    // ---- local worker processes (local_workers.cpp)
    void spawnWorker();
    void serveAsLocalWorker(int in, int out);
    void assignLocal(LocalWorker& w, std::size_t i);
    /// Waits up to `timeout_ms` (-1: until one answers) for answers of busy workers.
    bool collectLocal(int timeout_ms);
    /// A worker that stopped answering: its run fails, named with the signal that ended it.
    void workerDied(LocalWorker& w);
    void stopWorkers();
    int busyWorkers() const;

    // ---- worker ranks (rank_hand_out.cpp)
    bool serveRanks(int& stopped);
    /// "<index>\n[[dependency index, result], ...]": the results of the job's dependencies that
    /// rank has not been sent yet, so it can rebuild what the job reads.
    void assign(int rank, std::size_t i);
    /// Every result is in: tells each worker rank that the broadcast follows.
    void endPhaseOnRanks();

    const PoolOptions& o_;
    const std::string& plan_hash_;
    const std::vector<PoolJob>& jobs_;
    int local_slots_;
    const DependencyHook& on_dependency_;
    std::vector<std::optional<std::string>> results_;
    std::vector<std::optional<std::string>> failures_;
    std::vector<bool> is_dependency_;
    std::vector<std::set<std::size_t>> sent_;  ///< per rank: dependency results it has been sent
    std::vector<int> idle_ranks_;
    std::vector<std::size_t> pending_;
    std::vector<LocalWorker> workers_;
    std::map<std::size_t, Clock::time_point> remote_start_;
    int remote_running_ = 0;
    int total_ = 0, done_ = 0, failed_ = 0, executed_ = 0;
    double run_seconds_ = 0;
    Clock::time_point last_status_write_{};
    double dispatch_s_ = 0;  ///< [s] CPU time of the dispatcher's own work: hand-out, result files, status, polling
    Clock::time_point started_;
};

}  // namespace vroc::harness::pool_detail
