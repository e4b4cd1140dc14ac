// SPDX-License-Identifier: MIT
#include "scheduling/island_builder.h"

#include <numeric>
#include <utility>

namespace vroc::native {

void IslandBuilder::reset(const std::vector<bool>& infinite_mass) {
    infinite_mass_ = infinite_mass;
    parent_.resize(infinite_mass.size());
    std::iota(parent_.begin(), parent_.end(), 0);
}

int IslandBuilder::islandOf(int body) {
    if (infinite_mass_[static_cast<std::size_t>(body)]) return -1;
    int root = body;
    while (parent_[static_cast<std::size_t>(root)] != root) root = parent_[static_cast<std::size_t>(root)];
    while (parent_[static_cast<std::size_t>(body)] != root) {   // path compression
        const int next = parent_[static_cast<std::size_t>(body)];
        parent_[static_cast<std::size_t>(body)] = root;
        body = next;
    }
    return root;
}

void IslandBuilder::join(int a, int b) {
    if (infinite_mass_[static_cast<std::size_t>(a)] || infinite_mass_[static_cast<std::size_t>(b)]) return;
    int ra = islandOf(a), rb = islandOf(b);
    if (ra == rb) return;
    if (rb < ra) std::swap(ra, rb);
    parent_[static_cast<std::size_t>(rb)] = ra;   // the smaller index stays the root: order-free names
}

}  // namespace vroc::native
