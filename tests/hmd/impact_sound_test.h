// SPDX-License-Identifier: MIT
// Helpers of the impact sound tests: an onset detector that knows nothing of the synthesiser, and
// fresh temporary directories.
#pragma once

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <unistd.h>
#include <vector>

namespace vroc::audio::test {

/// Samples where a sound starts: the first sample whose magnitude exceeds `threshold` after at
/// least `quiet` samples at or below it (the track's start counts as quiet).
inline std::vector<std::size_t> detectOnsets(std::span<const float> samples, double threshold, std::size_t quiet) {
    std::vector<std::size_t> onsets;
    std::size_t below = quiet;   // consecutive samples at or below the threshold
    for (std::size_t n = 0; n < samples.size(); ++n) {
        if (std::fabs(samples[n]) <= threshold) {
            ++below;
            continue;
        }
        if (below >= quiet) onsets.push_back(n);
        below = 0;
    }
    return onsets;
}

/// Largest |sample| in [first, first + count).
inline double peakIn(std::span<const float> samples, std::size_t first, std::size_t count) {
    double peak = 0;
    for (std::size_t n = first; n < std::min(samples.size(), first + count); ++n)
        peak = std::max(peak, static_cast<double>(std::fabs(samples[n])));
    return peak;
}

inline std::filesystem::path freshDir(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / ("vroc-audio-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace vroc::audio::test
