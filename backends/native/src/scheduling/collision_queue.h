// SPDX-License-Identifier: MIT
// CollisionQueue: a min-heap of each pair's earliest possible collision time (Lin 1992, Mirtich's
// collision heap). Pairs far from collision sit deep in the heap and are not touched until their
// time comes. When a body's velocity changes (impulse, setBodyState) its pairs' keys are stale:
// invalidateBody() bumps the body's version and every entry stamped with the old version is
// dropped lazily when it surfaces (no search through the heap). Re-push the body's pairs after.
// Ordering is a strict total order (time, pair index, push stamp), so pops are identical for any
// insertion order of the same entries. Times are absolute [s] on the caller's clock.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

namespace vroc::native {

struct QueueEntry {
    double time = 0.0;        ///< [s] earliest possible collision time of the pair
    int pair = -1;            ///< caller's pair index (ties broken by it, smaller first)
    int body_a = -1;          ///< body index of A (its version is stamped)
    int body_b = -1;          ///< body index of B
};

struct CollisionQueueStats {
    std::int64_t pushes = 0;        ///< entries pushed
    std::int64_t pops = 0;          ///< valid entries returned by pop()
    std::int64_t stale_pops = 0;    ///< entries discarded because a version changed
    std::int64_t nan_times = 0;     ///< pushes whose time was NaN (treated as "check now")
    std::int64_t compactions = 0;   ///< heap rebuilds that dropped stale entries in bulk
};

class CollisionQueue {
public:
    /// Room for bodies [0, body_count) and pairs [0, pair_count); both grow on demand.
    explicit CollisionQueue(int body_count = 0, int pair_count = 0);

    /// Sets the pair's key to `time`, replacing any earlier key of that pair (the old entry goes
    /// stale). A NaN time becomes `now_if_nan` (counted): checking early is always safe.
    void push(int pair, int body_a, int body_b, double time, double now_if_nan = 0.0);
    /// Every entry that involves `body` becomes stale (its velocity changed).
    void invalidateBody(int body);
    /// The pair's entry becomes stale (the pair left the broad phase).
    void removePair(int pair);

    /// The earliest valid entry, removed; nullopt when none is left.
    std::optional<QueueEntry> pop();
    /// The earliest valid entry without removing it (stale tops are discarded on the way).
    std::optional<QueueEntry> top();
    /// Time of the earliest valid entry, +inf when empty.
    double nextTime();

    bool empty() { return !top().has_value(); }
    /// Entries stored, valid or stale (memory use; not the number of live pairs).
    std::size_t storedEntries() const { return heap_.size(); }
    const CollisionQueueStats& stats() const { return stats_; }
    void clear();

private:
    struct Slot {
        QueueEntry entry;
        std::uint32_t pair_stamp = 0;   // pair_stamp_[pair] at push time
        std::uint32_t version_a = 0;    // body_version_[body_a] at push time
        std::uint32_t version_b = 0;
    };
    static bool later(const Slot& x, const Slot& y);   // heap order: x pops after y
    bool isLive(const Slot& slot) const;
    void discardStaleTop();
    void compactIfMostlyStale();
    void ensureBody(int body);
    void ensurePair(int pair);

    std::vector<Slot> heap_;
    std::vector<std::uint32_t> body_version_;
    std::vector<std::uint32_t> pair_stamp_;
    std::vector<std::uint8_t> pair_live_;   // 1 while the pair has a current entry
    std::size_t live_count_ = 0;
    CollisionQueueStats stats_;
};

}  // namespace vroc::native
