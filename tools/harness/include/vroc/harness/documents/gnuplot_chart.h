// SPDX-License-Identifier: MIT
// Draws a chart (metrics_document.h) with gnuplot's SVG terminal, run as a subprocess on a data
// file and a script written next to the SVG, so the plotted data can be checked afterwards.
#pragma once

#include <filesystem>
#include <string>

#include "vroc/harness/documents/metrics_document.h"

namespace vroc::harness {

/// Writes <dir>/<id>.dat (one gnuplot index block per series, "x y" rows, %.17g), <id>.gp and
/// <id>.svg, and returns the SVG element text (XML prologue removed) for inlining.
/// Throws RunError if gnuplot cannot be run or fails (its message is in <id>.log).
std::string renderChart(const Json& chart, const std::filesystem::path& dir);

/// Escapes text for a double-quoted gnuplot string.
std::string gnuplotQuoted(const std::string& text);

}  // namespace vroc::harness
