// SPDX-License-Identifier: MIT
#include "frame_steps.h"

#include <cstdlib>

#include "vroc/core/errors.h"

namespace vroc::cli {

double parseFrameStep(const std::string& word, const std::string& option) {
    char* end = nullptr;
    double v = 0;
    if (word.rfind("1/", 0) == 0) {
        const double d = std::strtod(word.c_str() + 2, &end);
        v = d > 0 ? 1 / d : 0;
    } else {
        v = std::strtod(word.c_str(), &end);
    }
    if (word.empty() || *end != '\0' || !(v > 0))
        throw InputError(option + ": '" + word + "': expected a step in seconds (0.004 or 1/240)");
    return v;
}

std::vector<double> parseFrameSteps(const std::string& list, const std::string& option) {
    std::vector<double> out;
    std::string word;
    for (char c : list + ",") {
        if (c != ',') {
            word += c;
            continue;
        }
        out.push_back(parseFrameStep(word, option));
        word.clear();
    }
    return out;
}

}  // namespace vroc::cli
