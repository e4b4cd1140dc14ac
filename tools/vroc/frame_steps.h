// SPDX-License-Identifier: MIT
// Frame steps as users write them on the command line: seconds ("0.004") or a rate ("1/240").
#pragma once

#include <string>
#include <vector>

namespace vroc::cli {

/// "1/240" or "0.004" -> 0.004166.., 0.004 [s]; throws InputError naming `option` and the word.
double parseFrameStep(const std::string& word, const std::string& option = "--dt");

/// "1/60,1/120,0.002" -> seconds, in the order given.
std::vector<double> parseFrameSteps(const std::string& list, const std::string& option = "--dt");

}  // namespace vroc::cli
