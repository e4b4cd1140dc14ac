// SPDX-License-Identifier: MIT
#include "vroc/core/recording/output_dir.h"

#include <cctype>
#include <ctime>

namespace vroc::recording {

std::string utcNow(const char* format) {
    const std::time_t now = std::time(nullptr);
    std::tm utc{};
    gmtime_r(&now, &utc);
    char buf[64];
    const std::size_t n = std::strftime(buf, sizeof buf, format, &utc);
    return std::string(buf, n);
}

std::filesystem::path timestampedOutputDir(const std::vector<std::string>& words, const std::filesystem::path& parent) {
    std::string stem;
    for (const std::string& word : words) {
        std::string portable;
        for (char c : word) portable += (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-') ? c : '_';
        stem += (portable.empty() ? "unnamed" : portable) + "-";
    }
    stem += utcNow("%Y%m%d-%H%M%S");
    std::filesystem::path dir = parent / stem;
    for (int n = 2; std::filesystem::exists(dir); ++n) dir = parent / (stem + "-" + std::to_string(n));
    return dir;
}

}  // namespace vroc::recording
