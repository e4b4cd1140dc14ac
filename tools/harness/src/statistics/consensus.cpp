// SPDX-License-Identifier: MIT
#include "vroc/harness/statistics/consensus.h"

#include <algorithm>
#include <cmath>

#include "vroc/harness/documents/metrics_document.h"

namespace vroc::harness {
namespace {

// Backends that agree with every other voter only through their own noise (each difference is
// within their noise plus the floor, and beyond the other's noise plus the floor): whatever the
// others say, they would agree, so their agreement says nothing.
std::vector<std::size_t> uninformativeOf(const ConsensusInput& in, const std::vector<std::size_t>& idx) {
    std::vector<std::size_t> out;
    if (idx.size() < 3) return out;  // with two, the pair's verdict is all there is
    for (std::size_t i : idx) {
        if (!(in.noise[i] > in.floor)) continue;
        const bool only_by_own_noise = std::all_of(idx.begin(), idx.end(), [&](std::size_t j) {
            const double d = in.difference(i, j);
            return j == i || (std::isfinite(d) && d <= in.noise[i] + in.floor && d > in.noise[j] + in.floor);
        });
        if (only_by_own_noise) out.push_back(i);
    }
    if (out.size() + 2 > idx.size()) out.clear();  // keep at least two voters
    return out;
}

}  // namespace

ConsensusResult consensus(const ConsensusInput& in) {
    ConsensusResult out;
    std::vector<std::size_t> idx;
    for (std::size_t i = 0; i < in.backends.size(); ++i) {
        if (in.present[i]) {
            idx.push_back(i);
            continue;
        }
        const bool reason = i < in.absent_reason.size() && !in.absent_reason[i].empty();
        out.left_out.push_back(in.backends[i] + ": " + (reason ? in.absent_reason[i] : std::string("no value")));
    }
    const std::vector<std::size_t> quiet = uninformativeOf(in, idx);
    for (std::size_t i : quiet) out.uninformative.push_back(in.backends[i]);
    idx.erase(std::remove_if(idx.begin(), idx.end(),
                             [&](std::size_t i) { return std::find(quiet.begin(), quiet.end(), i) != quiet.end(); }),
              idx.end());
    const std::string suffix = out.uninformative.empty() ? "" : " (uninformative: " + joinText(out.uninformative) + ")";
    if (idx.size() < 2) {
        out.verdict = "too few values" + suffix;
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
        out.verdict = "all agree" + suffix;
        return out;
    }
    if (2 * group.size() > idx.size() && group.size() >= 2) {
        for (std::size_t i : idx)
            if (std::find(group.begin(), group.end(), i) == group.end()) out.outliers.push_back(in.backends[i]);
        out.verdict = "outlier: " + joinText(out.outliers) + suffix;
        return out;
    }
    out.verdict = "no majority" + suffix;
    return out;
}

}  // namespace vroc::harness
