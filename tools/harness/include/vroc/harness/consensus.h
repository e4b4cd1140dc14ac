// SPDX-License-Identifier: MIT
// Which backends agree on an observable, and which one is the odd one out: with three engines or
// more, differential testing can say more than "they differ" (docs/harness.md, compare).
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace vroc::harness {

/// One observable over n backends. Two backends agree when their difference is within the larger
/// of their own noise floors (twin-run spread) plus `floor`, the observable's stated resolution.
struct ConsensusInput {
    std::string observable;                        ///< e.g. "first contact [s]"
    std::vector<std::string> backends;
    std::vector<bool> present;                     ///< false: the backend has no value (no contact...)
    std::vector<double> noise;                     ///< per backend: |main - twin| of this observable
    std::function<double(std::size_t, std::size_t)> difference;   ///< >= 0, between backends i and j
    double floor = 0.0;                            ///< same units as the observable
    std::string floor_reason;                      ///< why that floor ("one frame: events are reported per frame")
};

struct ConsensusResult {
    std::vector<std::string> agreeing;   ///< the largest set in which every pair agrees
    std::vector<std::string> outliers;   ///< the others, when the agreeing set is a strict majority
    std::string verdict;                 ///< "all agree", "outlier: x", "no majority", "too few values"
};

/// Present backends only; the agreeing set is grown greedily from the backend with most
/// agreements (ties: input order), so the result is deterministic.
ConsensusResult consensus(const ConsensusInput& in);

}  // namespace vroc::harness
