// SPDX-License-Identifier: MIT
#include "vroc/harness/documents/metrics_document.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include "vroc/core/build_info.h"
#include "vroc/core/errors.h"
#include "vroc/core/recording/atomic_output.h"
#include "vroc/core/recording/run_record.h"

namespace vroc::harness {

Json number(double value) { return std::isfinite(value) ? Json(value) : Json(nullptr); }

Json chartJson(const ChartSpec& chart) {
    Json series = Json::array();
    for (const ChartSeries& s : chart.series) {
        Json x = Json::array(), y = Json::array();
        for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
            if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
            if ((chart.logx && s.x[i] <= 0) || (chart.logy && s.y[i] <= 0)) continue;
            x.push_back(s.x[i]);
            y.push_back(s.y[i]);
        }
        if (x.empty()) continue;
        series.push_back({{"name", s.name}, {"style", s.style}, {"x", x}, {"y", y}});
    }
    return {{"id", chart.id}, {"title", chart.title}, {"xlabel", chart.xlabel}, {"ylabel", chart.ylabel},
            {"logx", chart.logx}, {"logy", chart.logy}, {"series", series}};
}

Json tableJson(const std::string& id, const std::string& title, std::vector<std::string> columns,
               std::vector<std::vector<Json>> rows) {
    Json r = Json::array();
    for (auto& row : rows) r.push_back(Json(row));
    return {{"id", id}, {"title", title}, {"columns", columns}, {"rows", r}};
}

Json newDocument(const std::string& command, const std::string& command_line) {
    const BuildInfo& b = buildInfo();
    return {{"format", kMetricsFormat},
            {"command", command},
            {"command_line", command_line},
            {"created_utc", recording::utcNowIso8601()},
            {"build", {{"version", b.version}, {"commit", b.commit}, {"compiler", b.compiler}, {"flags", b.flags}}},
            {"tables", Json::array()},
            {"charts", Json::array()}};
}

void writeDocument(const Json& doc, const std::filesystem::path& path) {
    recording::AtomicFile file(path);
    file.write(doc.dump(2) + "\n");
    file.commit();
}

Json readDocument(const std::filesystem::path& path) {
    std::ifstream in(path);
    if (!in) throw InputError(path.string() + ": cannot open (expected a metrics.json written by vroc compare/check/sweep)");
    std::stringstream text;
    text << in.rdbuf();
    Json doc = Json::parse(text.str(), nullptr, false);
    if (doc.is_discarded() || !doc.is_object())
        throw InputError(path.string() + ": not valid JSON (expected a vroc-metrics/1 document)");
    if (doc.value("format", "") != kMetricsFormat)
        throw InputError(path.string() + ": $.format: expected \"" + std::string(kMetricsFormat) + "\"");
    for (const char* key : {"command", "tables", "charts"})
        if (!doc.contains(key)) throw InputError(path.string() + ": $." + key + ": missing");
    return doc;
}

std::string joinText(const std::vector<std::string>& parts, const char* separator) {
    std::string s;
    for (const std::string& p : parts) s += (s.empty() ? "" : separator) + p;
    return s;
}

}  // namespace vroc::harness
