// SPDX-License-Identifier: MIT
// The 3D replay in a command's output directory, <out>/view.html (docs/viewer.md): next to a
// `vroc compare` or `vroc ensemble` report, which links and frames it, and in a `vroc run`'s.
#pragma once

#include <filesystem>
#include <string>

namespace vroc::cli {

/// Writes <out>/view.html from the command's output directory. A failure is reported on stderr
/// ("vroc <command>: no 3D view: why") and does not fail the command: the run or report stands without it.
/// `penetration` false skips the penetration highlight (the neutral distance of every touching pair
/// at every kept frame, the costly part of the page) and says so in a note on the page: `vroc run`
/// does, unless --view-penetration, so that its view costs a small part of the run.
void writeReportView(const std::filesystem::path& out, const std::string& command, bool quiet, bool penetration = true);

}  // namespace vroc::cli
