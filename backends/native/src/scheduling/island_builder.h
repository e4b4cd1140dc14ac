// SPDX-License-Identifier: MIT
// IslandBuilder: bodies joined by touching contacts form islands (union-find, rebuilt whenever the
// touching set changes). Static (real) bodies join nothing: a floor does not merge the piles that
// rest on it. Each island is solved and scheduled on its own (docs/native-scheduling.md): an event
// in one island never shortens another island's step, and islands are the unit of parallel work.
// Deterministic: an island is named by its smallest body index, whatever the order of unions.
#pragma once

#include <vector>

namespace vroc::native {

class IslandBuilder {
public:
    /// Every body its own island; `infinite_mass[i]` bodies (static or tracked) never join one: they are ground.
    void reset(const std::vector<bool>& infinite_mass);
    /// Joins the islands of bodies a and b (no effect if either has infinite mass).
    void join(int a, int b);
    /// The island of `body`: its smallest body index (-1 for a body of infinite mass).
    int islandOf(int body);

private:
    std::vector<int> parent_;
    std::vector<bool> infinite_mass_;
};

}  // namespace vroc::native
