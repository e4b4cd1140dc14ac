// SPDX-License-Identifier: MIT
// RunPool (run_pool.h): a phase's runs go to the dispatcher on rank 0 (dispatcher.h) and are
// served by the other ranks; every rank gets the results back.
#include "vroc/harness/pool/run_pool.h"

#include <sched.h>

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <thread>

#include "dispatcher.h"
#include "interrupt.h"
#include "run_files.h"
#include "vroc/core/errors.h"
#include "vroc/harness/pool/mpi_world.h"

namespace vroc::harness {

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

RunPool::RunPool(PoolOptions options) : options_(std::move(options)), plan_hash_(pool_detail::planHash(options_.plan)) {
    if (options_.jobs < 0) throw InputError("--jobs: expected a positive number of runs at once (0 or absent: every core)");
    if (options_.jobs == 0) options_.jobs = mpi::size() > 1 ? 1 : defaultJobs();
    options_.jobs = std::min(options_.jobs, pool_detail::kMaxLocalWorkers);
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
        pool_detail::Dispatcher d(options_, plan_hash_, jobs, options_.jobs, on_dependency);
        if (options_.resume && !options_.runs_dir.empty()) resumed_ += d.resume();
        d.execute();
        dispatch_s_ += d.dispatchSeconds();
        outcome = d.outcome();
    } else {
        pool_detail::serveAsWorker(jobs, on_dependency);
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
