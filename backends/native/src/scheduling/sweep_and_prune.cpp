// SPDX-License-Identifier: MIT
#include "scheduling/sweep_and_prune.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vroc::native {

namespace {

// An update moves only the changed bodies' end points while fewer than 1 / this of the bodies
// changed; more, and the whole axes are rewritten and swept (as cheap, and no worse for many).
constexpr std::size_t kFewMovedFraction = 8;
// At most this many pairs added and removed by an update are put in place one by one; more are
// merged into the set in one pass.
constexpr std::size_t kFewChanges = 16;

BodyPair ordered(int x, int y) { return x < y ? BodyPair{x, y} : BodyPair{y, x}; }

void sortUnique(std::vector<BodyPair>& v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
}

}  // namespace

int SweepAndPrune::addBody(const Aabb& box, bool infinite_mass) {
    const int body = static_cast<int>(boxes_.size());
    boxes_.push_back(box);
    infinite_mass_.push_back(infinite_mass ? 1 : 0);
    removed_.push_back(0);
    moved_flag_.push_back(0);
    setAabb(body, box);
    // Appended after every other end point, lower before upper: as if the box came from +inf.
    for (int axis = 0; axis < 3; ++axis) {
        std::vector<EndPoint>& e = axes_[axis];
        e.push_back({std::numeric_limits<double>::infinity(), body, 0});
        e.push_back({std::numeric_limits<double>::infinity(), body, 1});
        slots_[axis].push_back(static_cast<std::int32_t>(e.size() - 2));
        slots_[axis].push_back(static_cast<std::int32_t>(e.size() - 1));
    }
    ++pending_new_;
    return body;
}

void SweepAndPrune::removeBody(int body) {
    if (body < 0 || body >= bodyCount() || removed_[body]) return;
    removed_[body] = 1;
    for (auto& axis : axes_) {
        axis.erase(std::remove_if(axis.begin(), axis.end(),
                                  [body](const EndPoint& e) { return e.body == body; }),
                   axis.end());
    }
    indexSlots();
    const auto before_size = pairs_.size();
    for (const BodyPair& p : pairs_)
        if (p.a == body || p.b == body) removed_with_bodies_.push_back(p);
    pairs_.erase(std::remove_if(pairs_.begin(), pairs_.end(),
                                [body](const BodyPair& p) { return p.a == body || p.b == body; }),
                 pairs_.end());
    stats_.pairs_removed += static_cast<std::int64_t>(before_size - pairs_.size());
}

void SweepAndPrune::recordChanges(const std::vector<BodyPair>& next) {
    std::set_difference(next.begin(), next.end(), pairs_.begin(), pairs_.end(), std::back_inserter(last_added_));
    std::set_difference(pairs_.begin(), pairs_.end(), next.begin(), next.end(), std::back_inserter(last_removed_));
}

void SweepAndPrune::setAabb(int body, const Aabb& box) {
    Aabb clean = box;
    bool bad = false;
    for (int axis = 0; axis < 3; ++axis) {
        double& lo = clean.lower[axis];
        double& hi = clean.upper[axis];
        if (std::isnan(lo)) { lo = -std::numeric_limits<double>::infinity(); bad = true; }
        if (std::isnan(hi)) { hi = std::numeric_limits<double>::infinity(); bad = true; }
        if (lo > hi) { std::swap(lo, hi); bad = true; }   // inverted: keep the sort consistent
    }
    if (bad) ++stats_.invalid_boxes;
    Aabb& kept = boxes_[body];
    if ((kept.lower != clean.lower || kept.upper != clean.upper) && moved_flag_[body] == 0) {
        moved_flag_[body] = 1;
        moved_.push_back(body);
    }
    kept = clean;
}

bool SweepAndPrune::pairAllowed(int x, int y) const {
    return x != y && !(infinite_mass_[x] && infinite_mass_[y]) && !removed_[x] && !removed_[y];
}

void SweepAndPrune::writeValues() {
    for (int axis = 0; axis < 3; ++axis) {
        for (EndPoint& e : axes_[axis]) {
            const Aabb& box = boxes_[e.body];
            e.value = e.is_upper ? box.upper[axis] : box.lower[axis];
        }
    }
}

void SweepAndPrune::onBegin(int body_x, int body_y) {
    if (pairAllowed(body_x, body_y) && boxes_[body_x].overlaps(boxes_[body_y])) {
        added_.push_back(ordered(body_x, body_y));
    }
}

void SweepAndPrune::onEnd(int body_x, int body_y) {
    if (pairAllowed(body_x, body_y)) dropped_.push_back(ordered(body_x, body_y));
}

void SweepAndPrune::sortAxis(int axis) {
    std::vector<EndPoint>& e = axes_[axis];
    for (std::size_t i = 1; i < e.size(); ++i) {
        if (!before(e[i], e[i - 1])) continue;   // the common coherent case: already in place
        const EndPoint key = e[i];
        std::size_t j = i;
        for (; j > 0 && before(key, e[j - 1]); --j) {
            const EndPoint& passed = e[j - 1];
            // key moves below `passed`: lower past upper starts an axis overlap, upper past
            // lower ends one; like ends passing each other change nothing.
            if (!key.is_upper && passed.is_upper) onBegin(key.body, passed.body);
            if (key.is_upper && !passed.is_upper) onEnd(key.body, passed.body);
            e[j] = e[j - 1];
            slot(axis, e[j]) = static_cast<std::int32_t>(j);
            ++stats_.swaps;
        }
        e[j] = key;
        slot(axis, key) = static_cast<std::int32_t>(j);
    }
}

void SweepAndPrune::indexSlots() {
    for (int axis = 0; axis < 3; ++axis) {
        slots_[axis].assign(2 * boxes_.size(), -1);
        for (std::size_t i = 0; i < axes_[axis].size(); ++i) slot(axis, axes_[axis][i]) = static_cast<std::int32_t>(i);
    }
}

void SweepAndPrune::moveEndPoint(int axis, std::size_t i) {
    std::vector<EndPoint>& e = axes_[axis];
    const EndPoint key = e[i];
    // Down past every end point it now sorts before (as the insertion sort moves it), then up past
    // every one that now sorts before it: a lower end passing above an upper one ends an axis
    // overlap, an upper end passing above a lower one starts one. Every pair whose order changes is
    // a candidate (updateMoved settles it by its boxes).
    for (; i > 0 && before(key, e[i - 1]); --i) {
        const EndPoint& passed = e[i - 1];
        if (key.is_upper != passed.is_upper && pairAllowed(key.body, passed.body))
            dropped_.push_back(ordered(key.body, passed.body));
        e[i] = passed;
        slot(axis, e[i]) = static_cast<std::int32_t>(i);
        ++stats_.swaps;
    }
    for (; i + 1 < e.size() && before(e[i + 1], key); ++i) {
        const EndPoint& passed = e[i + 1];
        if (key.is_upper != passed.is_upper && pairAllowed(key.body, passed.body))
            dropped_.push_back(ordered(key.body, passed.body));
        e[i] = passed;
        slot(axis, e[i]) = static_cast<std::int32_t>(i);
        ++stats_.swaps;
    }
    e[i] = key;
    slot(axis, key) = static_cast<std::int32_t>(i);
}

void SweepAndPrune::updateMoved() {
    // One end point at a time, its new value written just before it moves: the rest of the axis is
    // sorted by the values it holds, so each move leaves the axis sorted, the last one by the new
    // boxes (end points of equal value may stand in another order than the full sort's; the pairs
    // do not depend on it). Pairs are gathered in dropped_ whatever the direction (an end point of a
    // body not yet moved still holds its old value, so one pair may pass back and forth).
    std::sort(moved_.begin(), moved_.end());
    for (int body : moved_) {
        if (removed_[body]) continue;
        const Aabb& box = boxes_[body];
        for (int axis = 0; axis < 3; ++axis)
            for (std::int32_t upper = 0; upper < 2; ++upper) {
                const std::size_t i = static_cast<std::size_t>(slots_[axis][2 * static_cast<std::size_t>(body) + upper]);
                axes_[axis][i].value = upper != 0 ? box.upper[axis] : box.lower[axis];
                moveEndPoint(axis, i);
            }
    }
    // Each candidate settled by its boxes now: added if they overlap and were not in the set,
    // dropped if they were and no longer overlap.
    sortUnique(dropped_);
    std::size_t leaving = 0;
    for (const BodyPair& p : dropped_) {
        const bool had = std::binary_search(pairs_.begin(), pairs_.end(), p);
        if (boxes_[p.a].overlaps(boxes_[p.b])) {
            if (!had) added_.push_back(p);
        } else if (had) {
            dropped_[leaving++] = p;
        }
    }
    dropped_.resize(leaving);
    applyChanges();
}

void SweepAndPrune::applyChanges() {
    if (added_.empty() && dropped_.empty()) return;
    sortUnique(added_);
    sortUnique(dropped_);
    // What changes, found by binary search in the old set (a few pairs against many): a dropped
    // pair leaves if it was there; an added one enters unless it was there or is dropped again.
    auto had = [this](const BodyPair& p) { return std::binary_search(pairs_.begin(), pairs_.end(), p); };
    std::erase_if(added_, [&](const BodyPair& p) { return had(p) || std::binary_search(dropped_.begin(), dropped_.end(), p); });
    std::erase_if(dropped_, [&](const BodyPair& p) { return !had(p); });
    stats_.pairs_added += static_cast<std::int64_t>(added_.size());
    stats_.pairs_removed += static_cast<std::int64_t>(dropped_.size());
    last_added_.insert(last_added_.end(), added_.begin(), added_.end());
    last_removed_.insert(last_removed_.end(), dropped_.begin(), dropped_.end());
    if (added_.size() + dropped_.size() <= kFewChanges) {
        // A few changes: each put in its place (a shift of the sorted set, not a merge of it).
        for (const BodyPair& p : dropped_) pairs_.erase(std::lower_bound(pairs_.begin(), pairs_.end(), p));
        for (const BodyPair& p : added_) pairs_.insert(std::lower_bound(pairs_.begin(), pairs_.end(), p), p);
        added_.clear();
        dropped_.clear();
        return;
    }
    std::vector<BodyPair>& merged = merged_;
    merged.clear();
    std::set_union(pairs_.begin(), pairs_.end(), added_.begin(), added_.end(), std::back_inserter(merged));
    std::vector<BodyPair>& result = result_;  // trades storage with pairs_ below
    result.clear();
    std::set_difference(merged.begin(), merged.end(), dropped_.begin(), dropped_.end(), std::back_inserter(result));
    pairs_.swap(result);
    added_.clear();
    dropped_.clear();
}

void SweepAndPrune::rebuild() {
    // Many new bodies: insertion from +inf would cost O(n²) swaps; sort and sweep instead.
    auto order = [](const EndPoint& x, const EndPoint& y) {
        if (before(x, y)) return true;
        if (before(y, x)) return false;
        return x.body < y.body;
    };
    for (auto& axis : axes_) std::sort(axis.begin(), axis.end(), order);
    indexSlots();
    std::vector<BodyPair> found;
    std::vector<int> active;
    for (const EndPoint& e : axes_[0]) {
        if (e.is_upper) {
            const auto it = std::find(active.begin(), active.end(), e.body);
            if (it != active.end()) active.erase(it);
            continue;
        }
        for (int other : active) {
            if (pairAllowed(e.body, other) && boxes_[e.body].overlaps(boxes_[other])) {
                found.push_back(ordered(e.body, other));
            }
        }
        active.push_back(e.body);
    }
    sortUnique(found);
    const std::size_t added_before = last_added_.size(), removed_before = last_removed_.size();
    recordChanges(found);
    stats_.pairs_added += static_cast<std::int64_t>(last_added_.size() - added_before);
    stats_.pairs_removed += static_cast<std::int64_t>(last_removed_.size() - removed_before);
    pairs_.swap(found);
}

void SweepAndPrune::update() {
    ++stats_.updates;
    last_added_.clear();
    last_removed_.swap(removed_with_bodies_);
    removed_with_bodies_.clear();
    if (pending_new_ == 0 && kFewMovedFraction * moved_.size() <= boxes_.size()) {
        // Few boxes changed, or none (then the sorted axes and the pair set stand as they are: a
        // frame of one fixed tick sweeps the boxes of the frame, then of its tick, the same).
        if (!moved_.empty()) updateMoved();
    } else {
        writeValues();
        if (pending_new_ > 64 && 8 * pending_new_ > bodyCount()) {
            rebuild();
        } else {
            for (int axis = 0; axis < 3; ++axis) sortAxis(axis);
            applyChanges();
        }
        pending_new_ = 0;
    }
    for (int body : moved_) moved_flag_[body] = 0;
    moved_.clear();
    sortUnique(last_removed_);   // removeBody's pairs and this update's, in (a, b) order
}

}  // namespace vroc::native
