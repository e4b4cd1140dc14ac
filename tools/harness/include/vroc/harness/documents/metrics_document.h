// SPDX-License-Identifier: MIT
// metrics.json (format "vroc-metrics/1", docs/metrics-schema.md): every number a report shows.
// Reports are rendered from this document alone, so `vroc report` can rebuild them later.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace vroc::harness {

using Json = nlohmann::json;

inline constexpr const char* kMetricsFormat = "vroc-metrics/1";

struct ChartSeries {
    std::string name;
    std::string style = "lines";   ///< lines | points | linespoints | boxes | steps
    std::vector<double> x, y;
};

struct ChartSpec {
    std::string id;                ///< file-name safe, unique in the document
    std::string title;
    std::string xlabel, ylabel;    ///< with units, e.g. "t [s]"
    bool logx = false, logy = false;
    std::vector<ChartSeries> series;
};

/// The chart as stored in metrics.json. Drops points that cannot be drawn (non-finite, or <= 0 on
/// a log axis) and then empty series, so the stored series are exactly what gnuplot plots.
Json chartJson(const ChartSpec& chart);

/// A table: column headers (with units) and rows of numbers, strings or null.
Json tableJson(const std::string& id, const std::string& title, std::vector<std::string> columns,
               std::vector<std::vector<Json>> rows);

/// A new document: format, command, command line, creation time and build facts.
Json newDocument(const std::string& command, const std::string& command_line);

/// Writes `doc` as pretty JSON to `path` atomically (non-finite numbers become null).
void writeDocument(const Json& doc, const std::filesystem::path& path);
/// Reads and checks the format; throws InputError naming the file.
Json readDocument(const std::filesystem::path& path);

/// A JSON number, or null when not finite.
Json number(double value);

/// The parts joined with `separator` between them ("a, b, c"); "" for none.
std::string joinText(const std::vector<std::string>& parts, const char* separator = ", ");

}  // namespace vroc::harness
