// SPDX-License-Identifier: MIT
// SortedIndexSet: a set of small integers (pair indices) kept as a sorted vector. It iterates in
// ascending order, as std::set<int> does, but contiguously: the touching pairs are walked several
// times per internal step and change a few at a time, so a flat set beats a tree. The subset of
// std::set's interface the backend uses; insert and erase answer as std::set's do.
#pragma once

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace vroc::native {

class SortedIndexSet {
public:
    using const_iterator = std::vector<int>::const_iterator;

    /// {position, true} if `value` was added, {position, false} if it was there.
    std::pair<const_iterator, bool> insert(int value) {
        const auto it = std::lower_bound(values_.begin(), values_.end(), value);
        if (it != values_.end() && *it == value) return {it, false};
        return {values_.insert(it, value), true};
    }
    /// 1 if `value` was removed, 0 if it was not there.
    std::size_t erase(int value) {
        const auto it = std::lower_bound(values_.begin(), values_.end(), value);
        if (it == values_.end() || *it != value) return 0;
        values_.erase(it);
        return 1;
    }
    std::size_t count(int value) const { return std::binary_search(values_.begin(), values_.end(), value) ? 1 : 0; }
    std::size_t size() const { return values_.size(); }
    bool empty() const { return values_.empty(); }
    void clear() { values_.clear(); }
    const_iterator begin() const { return values_.begin(); }
    const_iterator end() const { return values_.end(); }

private:
    std::vector<int> values_;   // ascending, no repeats
};

}  // namespace vroc::native
