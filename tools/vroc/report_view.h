// SPDX-License-Identifier: MIT
// The 3D replay next to a `vroc compare` or `vroc ensemble` report: <out>/view.html, which
// report.html links and frames (docs/viewer.md).
#pragma once

#include <filesystem>
#include <string>

namespace vroc::cli {

/// Writes <out>/view.html from the command's output directory. A failure is reported on stderr
/// ("vroc <command>: no 3D view: why") and does not fail the command: the report stands without it.
void writeReportView(const std::filesystem::path& out, const std::string& command, bool quiet);

}  // namespace vroc::cli
