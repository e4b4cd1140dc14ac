// SPDX-License-Identifier: MIT
// `vroc report DIR...`: rebuilds report.html from metrics.json of earlier runs, or merges several
// into one page (one section per run, in the order given).
#pragma once

#include <filesystem>
#include <vector>

namespace vroc::harness {

/// Reads <dir>/metrics.json of every directory (InputError if missing or not vroc-metrics/1) and
/// writes <out_dir>/report.html. Returns its path.
std::filesystem::path rebuildReport(const std::vector<std::filesystem::path>& dirs, const std::filesystem::path& out_dir);

}  // namespace vroc::harness
