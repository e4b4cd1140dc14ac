// SPDX-License-Identifier: MIT
// The worker ranks under `mpirun` (dispatcher.h): rank 0 hands jobs out one at a time to every
// rank that asks, with the results of the jobs each one reads, and gathers what they return.
#include "dispatcher.h"
#include "run_files.h"
#include "vroc/harness/pool/mpi_world.h"

namespace vroc::harness::pool_detail {
namespace {

// MPI message tags of the hand-out protocol (rank 0 <-> worker ranks).
constexpr int kTagReady = 11;     // worker -> 0: idle, send me a job
constexpr int kTagAssign = 12;    // 0 -> worker: job index, or -1: no more in this phase
constexpr int kTagResult = 13;    // worker -> 0: "<index>\n<ok|fail>\n<result JSON | reason>"
constexpr int kTagPhaseEnd = 14;  // 0 -> worker: every result is in; the broadcast follows

}  // namespace

bool Dispatcher::serveRanks(int& stopped) {
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

void Dispatcher::assign(int rank, std::size_t i) {
    std::string deps = "[";
    auto& sent = sent_[static_cast<std::size_t>(rank)];
    for (std::size_t a : jobs_[i].after)
        if (sent.insert(a).second)
            deps += (deps.size() > 1 ? ",[" : "[") + std::to_string(a) + "," + *results_[a] + "]";
    remote_start_[i] = Clock::now();
    ++remote_running_;
    mpi::sendText(rank, kTagAssign, std::to_string(i) + "\n" + deps + "]");
}

void Dispatcher::endPhaseOnRanks() {
    for (int r = 1; r < mpi::size(); ++r) mpi::sendText(r, kTagPhaseEnd, "");
}

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

}  // namespace vroc::harness::pool_detail
