// SPDX-License-Identifier: MIT
// Default output directories of the commands that write files (`vroc run`, compare, check, sweep,
// ensemble): one name scheme, stamped with the UTC start time so runs never overwrite each other.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace vroc::recording {

/// <parent>/<word>-<word>-...-<YYYYmmdd-HHMMSS UTC>, e.g. runs/staircase-native-20261129-110711
/// (`vroc run`: scene, backend) or runs/compare-staircase-20261129-110711. Each word is made
/// portable (letters, digits, '.' and '-' kept, anything else '_'; empty -> "unnamed"); -2, -3,
/// ... is appended while the name is taken. Not created.
std::filesystem::path timestampedOutputDir(const std::vector<std::string>& words,
                                           const std::filesystem::path& parent = "runs");

/// The current UTC time formatted by strftime(`format`), e.g. "%Y-%m-%dT%H:%M:%SZ".
std::string utcNow(const char* format);

}  // namespace vroc::recording
