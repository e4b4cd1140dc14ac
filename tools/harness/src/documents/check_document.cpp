// SPDX-License-Identifier: MIT
#include "vroc/harness/documents/check_document.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "vroc/harness/documents/html_report.h"

namespace vroc::harness {
namespace {

std::string footingWord(const Footing& f) { return f.kind == Footing::Kind::Equal ? "equal" : "defaults"; }

// The table's first line: the footing every backend ran on, or both side by side.
std::string footingLine(const std::vector<SelectedBackend>& backends) {
    if (backends.empty()) return "defaults";
    if (!backends.front().both_footings) return footingText(backends.front().footing);
    std::string line = "both, side by side:";
    for (const SelectedBackend& b : backends)  // the first backend's two runs name both footings
        if (b.info == backends.front().info)
            line += std::string(line.back() == ':' ? " " : "; ") + "\"" + b.label().substr(b.info->name.size() + 1) +
                    "\" = " + footingText(b.footing);
    return line;
}

// A result cell as shown: pass / FAIL / info (reported, not judged), "n/s" when not supported,
// "n/v" when the run is not valid (the engine dropped contacts), with "~" when the backend
// approximates the scene.
std::string cellResult(const CheckCell& cell) {
    if (cell.support.level == Support::Unsupported) return "n/s";
    if (!cell.validity.valid) return "n/v";
    const std::string verdict = !cell.pass ? "info" : *cell.pass ? "pass" : "FAIL";
    return verdict + (cell.support.level == Support::Exact ? "" : "~");
}

Json rowJson(const CheckRow& row, const std::vector<SelectedBackend>& backends) {
    const CheckMetric& m = row.metric;
    Json results = Json::object();
    for (std::size_t b = 0; b < backends.size(); ++b) {
        const CheckCell& c = row.cells[b];
        Json& cell =
            results[backends[b].key()] = {{"measured", number(c.measured)},
                                          {"pass", c.pass ? Json(*c.pass) : Json(nullptr)},
                                          {"support", supportText(c.support)},
                                          {"not_valid", c.validity.valid ? Json(nullptr) : Json(c.validity.reason)}};
        if (backends[b].both_footings) cell["footing"] = footingWord(backends[b].footing);
    }
    return {{"id", m.id}, {"scenario", row.scenario}, {"title", m.title}, {"closed_form", m.closed_form},
            {"units", m.units}, {"expected", m.expected}, {"tolerance", number(m.tolerance)},
            {"criterion", m.criterion}, {"required_for_native", m.required_for_native}, {"results", results}};
}

Json checksTable(const CheckSuiteResult& r) {
    std::vector<std::string> columns = {"check", "closed form", "units", "expected", "tolerance", "tolerance: why", "required for native"};
    for (const SelectedBackend& b : r.backends) {
        columns.push_back(b.label() + " measured");
        columns.push_back(b.label() + " result");
    }
    std::vector<std::vector<Json>> rows;
    for (const CheckRow& row : r.rows) {
        const CheckMetric& m = row.metric;
        std::vector<Json> cells = {m.id, m.closed_form, m.units, m.expected, number(m.tolerance), m.criterion, m.required_for_native};
        for (const CheckCell& c : row.cells) {
            cells.push_back(number(c.measured));
            cells.push_back(cellResult(c));
        }
        rows.push_back(std::move(cells));
    }
    return tableJson("checks", "Checks x backends", columns, rows);
}

// Error relative to tolerance, per check, one series per backend (1 = the tolerance). Metrics
// that are reported but not judged, and cells not run, are left out; a non-finite result is drawn
// at 1e6, a zero error at 1e-6.
ChartSpec errorChart(const CheckSuiteResult& r) {
    ChartSpec chart{"check-errors", "Check error / tolerance (below 1 passes; zero errors drawn at 1e-6)",
                    "check number (table order)", "|measured - expected| / tolerance [-]", false, true, {}};
    for (std::size_t b = 0; b < r.backends.size(); ++b) {
        ChartSeries s{r.backends[b].label(), "points", {}, {}};
        for (std::size_t i = 0; i < r.rows.size(); ++i) {
            const CheckMetric& m = r.rows[i].metric;
            const CheckCell& c = r.rows[i].cells[b];
            if (!m.judged() || c.support.level == Support::Unsupported || !c.validity.valid) continue;
            const double err = std::isfinite(c.measured) ? std::abs(c.measured - m.expected) : 1e6;
            const double ratio = m.tolerance > 0 ? err / m.tolerance : (err > 0 ? 1e6 : 0);
            s.x.push_back(static_cast<double>(i + 1));
            s.y.push_back(std::max(ratio, 1e-6));
        }
        chart.series.push_back(s);
    }
    chart.series.push_back({"tolerance", "lines", {0.5, r.rows.size() + 0.5}, {1.0, 1.0}});
    return chart;
}

}  // namespace

Json checkDocument(const CheckSuiteResult& r, const std::string& command_line) {
    Json doc = newDocument("check", command_line);
    doc["title"] = std::string("analytic suite (") + (r.long_set ? "long" : "default") + " set)" + (r.stress ? " + stress section" : "");
    doc["backends"] = backendsJson(r.backends);
    doc["parameters"] = {{"long", r.long_set}, {"scenarios", r.scenario_count}, {"stress", r.stress}};
    if (r.stress) doc["parameters"]["scenes_dir"] = r.scenes_dir.string();
    Json checks = Json::array(), wall = Json::object();
    for (const CheckRow& row : r.rows) checks.push_back(rowJson(row, r.backends));
    for (std::size_t b = 0; b < r.backends.size(); ++b) wall[r.backends[b].key()] = r.wall_time_s[b];
    doc["results"] = {{"checks", checks}, {"wall_time_s", wall}, {"required_failures_native", r.required_failures_native}};
    doc["execution"] = executionJson(r.execution);
    doc["tables"].push_back(checksTable(r));
    doc["charts"].push_back(chartJson(errorChart(r)));
    return doc;
}

std::string checkTableText(const CheckSuiteResult& r) {
    std::string out = "footing: " + footingLine(r.backends) + "\n";
    char line[512];
    int width = 36;   // the check column: the longest id (stress ids are longer)
    for (const CheckRow& row : r.rows) width = std::max(width, static_cast<int>(row.metric.id.size()));
    std::snprintf(line, sizeof line, "%-*s %-5s %12s %10s", width, "check", "req", "expected", "tolerance");
    out += line;
    // A backend's column is as wide as its label ("bullet (equal footing)" with both footings).
    std::vector<int> label_width;
    for (const SelectedBackend& b : r.backends) {
        label_width.push_back(std::max(8, static_cast<int>(b.label().size())));
        std::snprintf(line, sizeof line, " | %-*s %12s %-5s", label_width.back(), b.label().c_str(), "measured", "");
        out += line;
    }
    out += "\n";
    for (const CheckRow& row : r.rows) {
        const CheckMetric& m = row.metric;
        char tolerance[32] = "-";
        if (m.judged()) std::snprintf(tolerance, sizeof tolerance, "%.3g", m.tolerance);
        std::snprintf(line, sizeof line, "%-*s %-5s %12.4g %10s", width, m.id.c_str(), m.required_for_native ? "yes" : "no",
                      m.expected, tolerance);
        out += line;
        for (std::size_t b = 0; b < row.cells.size(); ++b) {
            const CheckCell& c = row.cells[b];
            std::snprintf(line, sizeof line, " | %-*s %12s %-5s", label_width[b], "",
                          cellText(number(c.measured)).c_str(), cellResult(c).c_str());
            out += line;
        }
        out += "\n";
    }
    // Why a cell is "n/s", "n/v" or "~": one line per backend and reason.
    std::map<std::string, std::set<std::string>> why;
    for (const CheckRow& row : r.rows)
        for (std::size_t b = 0; b < r.backends.size(); ++b) {
            const CheckCell& c = row.cells[b];
            if (c.support.level != Support::Exact) why[r.backends[b].label()].insert(supportText(c.support));
            if (!c.validity.valid) why[r.backends[b].label()].insert(row.scenario + " n/v: " + c.validity.reason);
        }
    for (const auto& [n, reasons] : why)
        for (const std::string& reason : reasons) out += n + ": " + reason + "\n";
    return out;
}

}  // namespace vroc::harness
