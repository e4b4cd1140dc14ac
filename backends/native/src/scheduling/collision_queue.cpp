// SPDX-License-Identifier: MIT
#include "scheduling/collision_queue.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vroc::native {

CollisionQueue::CollisionQueue(int body_count, int pair_count) {
    if (body_count > 0) body_version_.assign(static_cast<std::size_t>(body_count), 0);
    if (pair_count > 0) {
        pair_stamp_.assign(static_cast<std::size_t>(pair_count), 0);
        pair_live_.assign(static_cast<std::size_t>(pair_count), 0);
    }
}

bool CollisionQueue::later(const Slot& x, const Slot& y) {
    if (x.entry.time != y.entry.time) return x.entry.time > y.entry.time;
    if (x.entry.pair != y.entry.pair) return x.entry.pair > y.entry.pair;
    return x.pair_stamp > y.pair_stamp;
}

void CollisionQueue::ensureBody(int body) {
    if (body >= static_cast<int>(body_version_.size())) body_version_.resize(body + 1, 0);
}

void CollisionQueue::ensurePair(int pair) {
    if (pair >= static_cast<int>(pair_stamp_.size())) {
        pair_stamp_.resize(pair + 1, 0);
        pair_live_.resize(pair + 1, 0);
    }
}

bool CollisionQueue::isLive(const Slot& slot) const {
    const QueueEntry& e = slot.entry;
    return pair_stamp_[e.pair] == slot.pair_stamp && pair_live_[e.pair] != 0 &&
           body_version_[e.body_a] == slot.version_a && body_version_[e.body_b] == slot.version_b;
}

void CollisionQueue::push(int pair, int body_a, int body_b, double time, double now_if_nan) {
    ensurePair(pair);
    ensureBody(std::max(body_a, body_b));
    if (std::isnan(time)) {
        ++stats_.nan_times;
        time = now_if_nan;
    }
    if (pair_live_[pair] == 0) ++live_count_;
    pair_live_[pair] = 1;
    Slot slot{{time, pair, body_a, body_b}, ++pair_stamp_[pair], body_version_[body_a],
              body_version_[body_b]};
    heap_.push_back(slot);
    std::push_heap(heap_.begin(), heap_.end(), later);
    ++stats_.pushes;
    compactIfMostlyStale();
}

void CollisionQueue::invalidateBody(int body) {
    ensureBody(body);
    ++body_version_[body];
    // live_count_ is recounted lazily: stale pairs are found when they surface or on compaction.
}

void CollisionQueue::removePair(int pair) {
    ensurePair(pair);
    if (pair_live_[pair] != 0) --live_count_;
    pair_live_[pair] = 0;
    ++pair_stamp_[pair];
}

void CollisionQueue::discardStaleTop() {
    while (!heap_.empty() && !isLive(heap_.front())) {
        const Slot& front = heap_.front();
        // A stale entry that is still its pair's current one (a body was invalidated and the
        // pair was not re-pushed) leaves the pair without an entry.
        if (pair_stamp_[front.entry.pair] == front.pair_stamp && pair_live_[front.entry.pair]) {
            pair_live_[front.entry.pair] = 0;
            --live_count_;
        }
        std::pop_heap(heap_.begin(), heap_.end(), later);
        heap_.pop_back();
        ++stats_.stale_pops;
    }
}

void CollisionQueue::compactIfMostlyStale() {
    // Bound memory: when stale entries outnumber live pairs 3:1 (plus slack), rebuild.
    if (heap_.size() < 64 || heap_.size() < 4 * live_count_) return;
    std::vector<Slot> kept;
    kept.reserve(heap_.size());
    std::size_t live = 0;
    for (const Slot& slot : heap_) {
        if (isLive(slot)) {
            kept.push_back(slot);
            ++live;
        } else if (pair_stamp_[slot.entry.pair] == slot.pair_stamp && pair_live_[slot.entry.pair]) {
            pair_live_[slot.entry.pair] = 0;
        }
    }
    heap_.swap(kept);
    std::make_heap(heap_.begin(), heap_.end(), later);
    live_count_ = live;
    ++stats_.compactions;
}

std::optional<QueueEntry> CollisionQueue::top() {
    discardStaleTop();
    if (heap_.empty()) return std::nullopt;
    return heap_.front().entry;
}

std::optional<QueueEntry> CollisionQueue::pop() {
    discardStaleTop();
    if (heap_.empty()) return std::nullopt;
    const QueueEntry entry = heap_.front().entry;
    std::pop_heap(heap_.begin(), heap_.end(), later);
    heap_.pop_back();
    pair_live_[entry.pair] = 0;
    --live_count_;
    ++stats_.pops;
    return entry;
}

double CollisionQueue::nextTime() {
    const auto t = top();
    return t ? t->time : std::numeric_limits<double>::infinity();
}

void CollisionQueue::clear() {
    heap_.clear();
    std::fill(pair_live_.begin(), pair_live_.end(), 0);
    for (auto& s : pair_stamp_) ++s;
    live_count_ = 0;
}

}  // namespace vroc::native
