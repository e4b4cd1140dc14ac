// SPDX-License-Identifier: MIT
// Default output directories of the harness commands: runs/<command>-<name>-<YYYYmmdd-HHMMSS UTC>.
#pragma once

#include <filesystem>
#include <string>

namespace vroc::harness {

/// A fresh directory name (with -2, -3, ... when taken); not created.
std::filesystem::path defaultOutputDir(const std::string& command, const std::string& name);

}  // namespace vroc::harness
