// SPDX-License-Identifier: MIT
#include "vroc/harness/consensus.h"

#include <algorithm>
#include <cmath>

namespace vroc::harness {

ConsensusResult consensus(const ConsensusInput& in) {
    ConsensusResult out;
    std::vector<std::size_t> idx;
    for (std::size_t i = 0; i < in.backends.size(); ++i)
        if (in.present[i]) idx.push_back(i);
    if (idx.size() < 2) {
        out.verdict = "too few values";
        for (std::size_t i : idx) out.agreeing.push_back(in.backends[i]);
        return out;
    }
    auto agree = [&](std::size_t a, std::size_t b) {
        const double d = in.difference(a, b);
        return std::isfinite(d) && d <= std::max(in.noise[a], in.noise[b]) + in.floor;
    };
    std::vector<int> count(in.backends.size(), 0);
    for (std::size_t a : idx)
        for (std::size_t b : idx)
            if (a != b && agree(a, b)) ++count[a];
    std::vector<std::size_t> order = idx;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return count[a] > count[b]; });
    std::vector<std::size_t> group;
    for (std::size_t c : order)
        if (std::all_of(group.begin(), group.end(), [&](std::size_t g) { return agree(g, c); })) group.push_back(c);
    std::sort(group.begin(), group.end());
    for (std::size_t g : group) out.agreeing.push_back(in.backends[g]);
    if (group.size() == idx.size()) {
        out.verdict = "all agree";
        return out;
    }
    if (2 * group.size() > idx.size() && group.size() >= 2) {
        for (std::size_t i : idx)
            if (std::find(group.begin(), group.end(), i) == group.end()) out.outliers.push_back(in.backends[i]);
        out.verdict = "outlier: ";
        for (std::size_t k = 0; k < out.outliers.size(); ++k) out.verdict += (k ? ", " : "") + out.outliers[k];
        return out;
    }
    out.verdict = "no majority";
    return out;
}

}  // namespace vroc::harness
