// SPDX-License-Identifier: MIT
// Independent runs spread over local worker processes and MPI ranks, with results identical to
// running them one after another (docs/harness.md, "Many runs at once").
//
// A command lists its runs as jobs (an id and a function returning the run's result as JSON) and
// hands them to RunPool::run, which returns the results in job order. How they ran does not show:
// - `--jobs 1`, one rank: in this process, one after another;
// - `--jobs N`: N forked worker processes at a time (a crash costs one run, not the command);
// - under `mpirun -n R`: rank 0 hands jobs out one at a time to every rank, runs `--jobs` of its own
//   in forked workers, gathers each result and broadcasts them all back, so that every rank goes on
//   with the same results (a later phase may depend on an earlier one's, as a sweep's runs depend
//   on its reference runs).
// Every result passes through its JSON text (whose doubles round-trip exactly), so the results, and
// the metrics made from them, are the same bits whichever way they ran.
//
// Each finished run is written at once to `<runs_dir>/<id>.json`, marked with the hash of the plan
// (what the runs depend on). `--resume` loads those whose plan matches and runs only the rest. An
// interrupt (Ctrl-C, a killed rank, a cancelled job) stops the workers, prints which runs did not
// finish and how to resume, and leaves `<runs_dir>/status.json` listing them.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "vroc/harness/documents/metrics_document.h"

namespace vroc::harness {

struct PoolJob {
    std::string id;                 ///< unique in the command, file-name safe (poolJobId)
    std::function<Json()> run;      ///< the run; throws for a failure (counted, named, not fatal to others)
    /// Relative cost estimate (e.g. frames to step). Costlier jobs are handed out first so that a
    /// long run does not start last and leave the other workers idle; results keep job order.
    double cost = 0;
    /// Indices (in the same run() call) of jobs whose results this one reads: it starts only after
    /// they finished, and fails, named, if one of them failed.
    std::vector<std::size_t> after = {};
};

/// Called with (job index, result) for every job another job depends on, in each process that
/// runs a dependent job and before that job starts: the caller stores what its dependents read
/// (a sweep's reference trace). On rank 0 it is called for every such job as it finishes.
using DependencyHook = std::function<void(std::size_t, const Json&)>;

struct PoolProgress {
    int total = 0;             ///< runs in this phase
    int done = 0;              ///< finished (resumed ones included)
    int failed = 0;
    double seconds_left = -1;  ///< estimate; < 0 while unknown
};

struct PoolOptions {
    int jobs = 0;                          ///< local runs at once; 0: every core (one per rank under MPI)
    std::filesystem::path runs_dir;        ///< where each finished run is written (created, one fsync'd file a run);
                                           ///< empty: nowhere (no --resume), results come back over the workers'
                                           ///< pipes; MPI ranks need it
    bool resume = false;                   ///< load finished runs of the same plan instead of rerunning them
    Json plan;                             ///< everything the runs depend on; hashed into each run file
    std::string command = "vroc";          ///< for messages, e.g. "vroc sweep"
    std::function<void(const PoolProgress&)> progress;   ///< called on rank 0 as runs finish; may be empty
};

/// How a command's runs were executed, for its report.
struct PoolExecution {
    int jobs = 1;               ///< local runs at once per rank
    int ranks = 1;              ///< MPI ranks
    std::string mpi_library;    ///< "Open MPI v4.1.4, ..." or "none"
    int runs = 0;               ///< runs executed or resumed, over every phase
    int resumed = 0;            ///< loaded from a previous attempt (--resume)
    double dispatch_s = 0;      ///< [s] CPU time rank 0's dispatcher spent handing runs out, storing
                                ///< their results and polling (0 when the runs went in this process)

    /// Runs that may have shared the machine with each other (timings are then not alone).
    int atOnce() const { return jobs * ranks; }
};

/// {jobs, ranks, mpi_library, runs, resumed, dispatch_s}: the "execution" member of metrics.json.
Json executionJson(const PoolExecution& execution);

/// "ref-native-dt=1/960" -> "ref-native-dt_1_960": letters, digits and . _ = - kept.
std::string poolJobId(const std::string& text);

/// The default for `--jobs`: the number of cores this process may use.
int defaultJobs();

class RunPool {
public:
    /// Throws InputError if `runs_dir` cannot be created, or (with resume) holds runs of another plan.
    explicit RunPool(PoolOptions options);

    /// Every job here, one after another, writing nothing (library callers and tests).
    static RunPool inProcess();

    /// Runs the jobs (collective: every MPI rank calls it with the same list), each as soon as its
    /// dependencies are done, costliest first, and returns their results in job order on every rank. Throws RunError naming the failed runs once all others
    /// have finished; the finished ones stay on disk for --resume.
    std::vector<Json> run(const std::vector<PoolJob>& jobs, const DependencyHook& on_dependency = {});

    /// How the runs were executed so far (over every phase).
    PoolExecution execution() const;

private:
    PoolOptions options_;
    std::string plan_hash_;
    int runs_ = 0;      ///< over every phase
    int resumed_ = 0;
    double dispatch_s_ = 0;
};

}  // namespace vroc::harness
