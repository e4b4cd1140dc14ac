// SPDX-License-Identifier: MIT
// report.html: one self-contained page (no network) rendered from metrics documents alone:
// summary tables first, then the charts (inline gnuplot SVG), then settings, versions and build.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "vroc/harness/documents/metrics_document.h"

namespace vroc::harness {

/// Renders every document (several when merging runs) into <out_dir>/report.html, with chart
/// data, scripts and SVGs in <out_dir>/charts/. Returns the report's path.
std::filesystem::path writeReport(const std::vector<Json>& documents, const std::filesystem::path& out_dir);

/// Escapes &, <, >, " for HTML text and attributes.
std::string htmlEscaped(const std::string& text);

/// A table cell as shown: numbers with 4 significant digits, null as an em dash.
std::string cellText(const Json& cell);

}  // namespace vroc::harness
