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
/// A backend whose own noise floor spans every difference among the others is uninformative: it
/// would agree with anyone, so it does not vote (and is named).
struct ConsensusInput {
    std::string observable;                        ///< e.g. "first contact [s]"
    std::vector<std::string> backends;
    std::vector<bool> present;                     ///< false: the backend has no value (no contact...)
    std::vector<std::string> absent_reason;        ///< per backend, why it is not present (empty: none given)
    std::vector<double> noise;                     ///< per backend: |main - twin| of this observable
    std::function<double(std::size_t, std::size_t)> difference;   ///< >= 0, between backends i and j
    double floor = 0.0;                            ///< same units as the observable
    std::string floor_reason;                      ///< why that floor ("one frame: events are reported per frame")
};

struct ConsensusResult {
    std::vector<std::string> agreeing;   ///< the largest set in which every pair agrees
    std::vector<std::string> outliers;   ///< the others, when the agreeing set is a strict majority
    std::vector<std::string> left_out;   ///< "name: why" for each backend not present (no value, not valid)
    std::vector<std::string> uninformative;  ///< backends whose noise floor spans every other difference
    std::string verdict;                 ///< "all agree", "outlier: x", "no majority", "too few values"
};

/// Present, informative backends vote; the agreeing set is grown greedily from the backend with
/// most agreements (ties: input order), so the result is deterministic.
ConsensusResult consensus(const ConsensusInput& in);

}  // namespace vroc::harness
