// SPDX-License-Identifier: MIT
// PairPartition: the 1995 paper's distribution of object pairs over processors, round robin
// (pair i goes to worker i mod N), run on a tiny persistent thread pool. Determinism does not
// depend on N because (1) every pair's work is a pure function of that pair's inputs, run by
// exactly one worker, and (2) per-worker outputs are merged in an order defined by the data
// (pair index, or a caller-given strict total order such as (time, pair)), never by which worker
// finished first. Reductions over pairs must then run serially over the merged result.
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>
#include <memory>
#include <vector>

namespace vroc::native {

class PairPartition {
public:
    /// `workers` >= 1 (clamped). Worker 0 is the calling thread; N − 1 threads are started once.
    explicit PairPartition(int workers);
    ~PairPartition();
    PairPartition(const PairPartition&) = delete;
    PairPartition& operator=(const PairPartition&) = delete;

    int workers() const { return workers_; }
    /// The worker that owns pair `index` (round robin).
    static int ownerOf(std::size_t index, int workers) {
        return static_cast<int>(index % static_cast<std::size_t>(workers));
    }

    /// Calls fn(index, worker) for every index in [0, count) on its owner; returns when all are
    /// done. If calls throw, the exception of the lowest worker is rethrown here.
    void run(std::size_t count, const std::function<void(std::size_t, int)>& fn);

    /// results[i] = fn(i) for i in [0, count): identical for any worker count.
    template <class R, class Fn>
    std::vector<R> map(std::size_t count, Fn fn) {
        std::vector<R> results(count);
        run(count, [&](std::size_t i, int) { results[i] = fn(i); });
        return results;
    }

    /// fn(i, out) appends any number of events for pair i to `out` (a per-worker list). The
    /// lists are merged and sorted by `less`, which must be a strict total order on events
    /// (e.g. by time, then pair index): the merged list is then identical for any worker count.
    template <class Event, class Fn, class Less>
    std::vector<Event> collect(std::size_t count, Fn fn, Less less) {
        std::vector<std::vector<Event>> per_worker(static_cast<std::size_t>(workers_));
        run(count, [&](std::size_t i, int w) { fn(i, per_worker[static_cast<std::size_t>(w)]); });
        std::vector<Event> merged;
        for (auto& list : per_worker) merged.insert(merged.end(), list.begin(), list.end());
        std::sort(merged.begin(), merged.end(), less);
        return merged;
    }

    /// fn(i) for every i in [0, count), shared by the workers in runs of `share` consecutive
    /// indices (a run is worth the hand-over); serially if one worker or one run. fn must touch
    /// nothing but what belongs to i: then the same bits for any worker count.
    template <class Fn>
    void forEachShared(std::size_t count, std::size_t share, const Fn& fn) {
        const std::size_t shares = (count + share - 1) / share;
        if (workers_ <= 1 || shares <= 1) {
            for (std::size_t i = 0; i < count; ++i) fn(i);
            return;
        }
        // Two references captured: std::function keeps them in place (no allocation per call).
        const std::size_t range[2] = {count, share};
        run(shares, [&fn, &range](std::size_t k, int) {
            for (std::size_t i = k * range[1]; i < std::min(range[0], (k + 1) * range[1]); ++i) fn(i);
        });
    }

private:
    struct Pool;
    int workers_ = 1;
    std::unique_ptr<Pool> pool_;
};

}  // namespace vroc::native
