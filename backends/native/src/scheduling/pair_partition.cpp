// SPDX-License-Identifier: MIT
#include "scheduling/pair_partition.h"

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <thread>

namespace vroc::native {

// Threads wait for a new generation, run their share, report done. One job at a time.
// A step hands out many small jobs in quick succession (a few pairs to sample, a few islands to
// solve), so a worker first spins briefly on the generation counter and sleeps on the condition
// variable only when none comes: waking a sleeping thread costs tens of microseconds, more than
// such a job. The caller likewise spins for its workers' shares before it sleeps.
struct PairPartition::Pool {
    /// Spin iterations (each a CPU pause, ~10-40 ns) before sleeping: some tens of microseconds.
    static constexpr int kSpins = 4000;

    std::mutex mutex;
    std::condition_variable start;
    std::condition_variable done;
    std::atomic<std::uint64_t> generation{0};
    std::atomic<int> pending{0};
    std::atomic<bool> caller_sleeps{false};   // the caller waits on `done`: the last worker notifies
    bool stopping = false;                    // under mutex
    // The current job: fn(i, worker) for i in [0, count), i = worker mod stride. Plain fields, not
    // a std::function of a capturing lambda: handing a job to the workers allocates nothing.
    // Written before `generation` is raised (release), read after it is seen (acquire).
    const std::function<void(std::size_t, int)>* job = nullptr;
    std::size_t job_count = 0;
    std::vector<std::exception_ptr> errors;   // each worker its own slot, read after pending is 0
    std::vector<std::thread> threads;

    static void pause() {
#if defined(__x86_64__) || defined(__i386__)
        __builtin_ia32_pause();
#else
        std::this_thread::yield();
#endif
    }

    /// Worker `worker`'s share of fn over [0, count): every index it owns (PairPartition::ownerOf).
    void share(const std::function<void(std::size_t, int)>& fn, std::size_t count, int worker) const {
        const auto stride = threads.size() + 1;
        for (std::size_t i = static_cast<std::size_t>(worker); i < count; i += stride) fn(i, worker);
    }

    void loop(int worker) {
        std::uint64_t seen = 0;
        for (;;) {
            int spins = 0;
            while (generation.load(std::memory_order_acquire) == seen && spins < kSpins) {
                pause();
                ++spins;
            }
            if (generation.load(std::memory_order_acquire) == seen) {
                std::unique_lock lock(mutex);
                start.wait(lock, [&] { return stopping || generation.load(std::memory_order_acquire) != seen; });
                if (stopping) return;
            }
            seen = generation.load(std::memory_order_acquire);
            std::exception_ptr error;
            try {
                share(*job, job_count, worker);
            } catch (...) {
                error = std::current_exception();
            }
            errors[static_cast<std::size_t>(worker)] = error;
            // seq_cst with the caller's store of caller_sleeps and load of pending: one of the two
            // sees the other, so the caller never sleeps through the last share.
            if (pending.fetch_sub(1, std::memory_order_seq_cst) == 1 && caller_sleeps.load(std::memory_order_seq_cst)) {
                std::lock_guard lock(mutex);   // the caller checks `pending` under the mutex before sleeping
                done.notify_one();
            }
        }
    }
};

PairPartition::PairPartition(int workers)
    : workers_(std::max(1, workers)), pool_(std::make_unique<Pool>()) {
    pool_->errors.resize(static_cast<std::size_t>(workers_));
    for (int w = 1; w < workers_; ++w) pool_->threads.emplace_back([this, w] { pool_->loop(w); });
}

PairPartition::~PairPartition() {
    {
        std::lock_guard lock(pool_->mutex);
        pool_->stopping = true;
    }
    pool_->start.notify_all();
    for (auto& t : pool_->threads) t.join();
}

void PairPartition::run(std::size_t count, const std::function<void(std::size_t, int)>& fn) {
    if (workers_ == 1 || count <= 1) {
        // Same owners as the threaded path would use, so per-worker outputs match it.
        const auto stride = static_cast<std::size_t>(workers_);
        for (int w = 0; w < workers_; ++w)
            for (std::size_t i = static_cast<std::size_t>(w); i < count; i += stride) fn(i, w);
        return;
    }
    pool_->job = &fn;
    pool_->job_count = count;
    std::fill(pool_->errors.begin(), pool_->errors.end(), nullptr);
    pool_->pending.store(workers_ - 1, std::memory_order_relaxed);
    {
        // Raised under the mutex, so a worker between its check and its sleep cannot miss it.
        std::lock_guard lock(pool_->mutex);
        pool_->generation.fetch_add(1, std::memory_order_release);
    }
    pool_->start.notify_all();
    std::exception_ptr mine;
    try {
        pool_->share(fn, count, 0);
    } catch (...) {
        mine = std::current_exception();
    }
    for (int spins = 0; pool_->pending.load(std::memory_order_acquire) != 0 && spins < Pool::kSpins; ++spins) Pool::pause();
    if (pool_->pending.load(std::memory_order_acquire) != 0) {
        std::unique_lock lock(pool_->mutex);
        pool_->caller_sleeps.store(true, std::memory_order_seq_cst);
        pool_->done.wait(lock, [&] { return pool_->pending.load(std::memory_order_seq_cst) == 0; });
        pool_->caller_sleeps.store(false, std::memory_order_relaxed);
    }
    pool_->job = nullptr;
    if (mine) std::rethrow_exception(mine);
    for (const auto& e : pool_->errors) {
        if (e) std::rethrow_exception(e);
    }
}

}  // namespace vroc::native
