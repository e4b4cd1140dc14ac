// SPDX-License-Identifier: MIT
// "Did you mean ...?" suggestions for unknown keys and names in input files (internal).
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace vroc {

/// Optimal-string-alignment distance: insertions, deletions, substitutions and adjacent
/// transpositions each cost 1 (so "restituion" -> "restitution" is 1, "fritcion" -> "friction" is 1).
int editDistance(std::string_view a, std::string_view b);

/// The candidate nearest to `word` by editDistance (first one on ties, so the answer is
/// deterministic); "" if there are no candidates.
std::string nearestWord(std::string_view word, std::span<const std::string> candidates);

}  // namespace vroc
