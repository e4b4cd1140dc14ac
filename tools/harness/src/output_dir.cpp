// SPDX-License-Identifier: MIT
#include "vroc/harness/output_dir.h"

#include <cctype>
#include <ctime>

namespace vroc::harness {

std::filesystem::path defaultOutputDir(const std::string& command, const std::string& name) {
    std::string word;
    for (char c : name) word += (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-') ? c : '_';
    const std::time_t now = std::time(nullptr);
    std::tm utc{};
    gmtime_r(&now, &utc);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &utc);
    const std::string stem = "runs/" + command + "-" + (word.empty() ? "all" : word) + "-" + stamp;
    std::filesystem::path dir = stem;
    for (int n = 2; std::filesystem::exists(dir); ++n) dir = stem + "-" + std::to_string(n);
    return dir;
}

}  // namespace vroc::harness
