// SPDX-License-Identifier: MIT
#include "scheduling/pair_partition.h"

#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <thread>

namespace vroc::native {

// Threads wait for a new generation, run their share, report done. One job at a time.
struct PairPartition::Pool {
    std::mutex mutex;
    std::condition_variable start;
    std::condition_variable done;
    std::uint64_t generation = 0;
    int pending = 0;
    bool stopping = false;
    // The current job: fn(i, worker) for i in [0, count), i = worker mod stride. Plain fields, not
    // a std::function of a capturing lambda: handing a job to the workers allocates nothing.
    const std::function<void(std::size_t, int)>* job = nullptr;
    std::size_t job_count = 0;
    std::vector<std::exception_ptr> errors;
    std::vector<std::thread> threads;

    /// Worker `worker`'s share of fn over [0, count): every index it owns (PairPartition::ownerOf).
    void share(const std::function<void(std::size_t, int)>& fn, std::size_t count, int worker) const {
        const auto stride = threads.size() + 1;
        for (std::size_t i = static_cast<std::size_t>(worker); i < count; i += stride) fn(i, worker);
    }

    void loop(int worker) {
        std::uint64_t seen = 0;
        for (;;) {
            const std::function<void(std::size_t, int)>* current = nullptr;
            std::size_t count = 0;
            {
                std::unique_lock lock(mutex);
                start.wait(lock, [&] { return stopping || generation != seen; });
                if (stopping) return;
                seen = generation;
                current = job;
                count = job_count;
            }
            std::exception_ptr error;
            try {
                share(*current, count, worker);
            } catch (...) {
                error = std::current_exception();
            }
            std::lock_guard lock(mutex);
            errors[static_cast<std::size_t>(worker)] = error;
            if (--pending == 0) done.notify_one();
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
    {
        std::lock_guard lock(pool_->mutex);
        pool_->job = &fn;
        pool_->job_count = count;
        pool_->pending = workers_ - 1;
        std::fill(pool_->errors.begin(), pool_->errors.end(), nullptr);
        ++pool_->generation;
    }
    pool_->start.notify_all();
    std::exception_ptr mine;
    try {
        pool_->share(fn, count, 0);
    } catch (...) {
        mine = std::current_exception();
    }
    std::unique_lock lock(pool_->mutex);
    pool_->done.wait(lock, [&] { return pool_->pending == 0; });
    pool_->job = nullptr;
    if (mine) std::rethrow_exception(mine);
    for (const auto& e : pool_->errors) {
        if (e) std::rethrow_exception(e);
    }
}

}  // namespace vroc::native
