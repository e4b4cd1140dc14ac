// SPDX-License-Identifier: MIT
#include "vroc/harness/documents/html_report.h"

#include <cstdio>
#include <sstream>

#include "vroc/core/recording/atomic_output.h"
#include "vroc/harness/documents/gnuplot_chart.h"

namespace vroc::harness {
namespace fs = std::filesystem;

std::string htmlEscaped(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
    }
    return out;
}

std::string cellText(const Json& cell) {
    if (cell.is_null()) return "\u2014";
    if (cell.is_boolean()) return cell.get<bool>() ? "yes" : "no";
    if (cell.is_number_integer()) return std::to_string(cell.get<long long>());
    if (cell.is_number()) {
        char buf[48];
        std::snprintf(buf, sizeof buf, "%.4g", cell.get<double>());
        return buf;
    }
    if (cell.is_string()) return cell.get<std::string>();
    return cell.dump();
}

namespace {

constexpr const char* kStyle = R"(body{font-family:sans-serif;margin:24px;max-width:1100px;color:#222}
table{border-collapse:collapse;margin:8px 0 20px}td,th{border:1px solid #bbb;padding:3px 8px;text-align:right}
th{background:#eef}td:first-child,th:first-child{text-align:left}.text{text-align:left}.pass{background:#dfd}.fail{background:#fbb;font-weight:bold}
figure{margin:12px 0 28px}figcaption{font-weight:bold}h2{border-bottom:2px solid #88a;margin-top:36px}
pre{background:#f4f4f4;padding:8px;white-space:pre-wrap}
.eff-large{background:#f99}.eff-medium{background:#fc9}.eff-small{background:#ffc}.eff-none{background:#f7f7f7;color:#555}.eff-na{background:#ddd;color:#555;font-style:italic})";

std::string tableHtml(const Json& table) {
    std::ostringstream h;
    h << "<h3>" << htmlEscaped(table.value("title", "")) << "</h3>\n<table id=\"table-" << htmlEscaped(table.value("id", ""))
      << "\"><tr>";
    for (const Json& c : table["columns"]) h << "<th>" << htmlEscaped(c.get<std::string>()) << "</th>";
    h << "</tr>\n";
    // Optional "cell_classes": rows of CSS class names, one per cell ("" for none), e.g. an effect's colour.
    const Json classes = table.value("cell_classes", Json::array());
    for (std::size_t r = 0; r < table["rows"].size(); ++r) {
        const Json& row = table["rows"][r];
        h << "<tr>";
        for (std::size_t c = 0; c < row.size(); ++c) {
            const Json& cell = row[c];
            const std::string text = cellText(cell);
            std::string cls = text == "pass" ? "pass" : text == "FAIL" ? "fail" : cell.is_string() ? "text" : "";
            if (r < classes.size() && c < classes[r].size() && !classes[r][c].get<std::string>().empty())
                cls += (cls.empty() ? "" : " ") + classes[r][c].get<std::string>();
            h << "<td" << (cls.empty() ? "" : " class=\"" + htmlEscaped(cls) + "\"") << ">" << htmlEscaped(text)
              << "</td>";
        }
        h << "</tr>\n";
    }
    return h.str() + "</table>\n";
}

std::string settingsHtml(const Json& doc) {
    std::ostringstream h;
    h << "<h3>Settings, versions and build</h3>\n";
    if (doc.contains("scene")) h << "<p>Scene: <code>" << htmlEscaped(doc["scene"].dump()) << "</code></p>\n";
    if (doc.contains("backends")) {
        // The footing the engines ran on (the same for all of them, or both side by side: every
        // engine twice, each entry labelled), and per engine what it set.
        const Json first = doc["backends"].empty() ? Json::object() : doc["backends"][0];
        const Json footing = first.value("footing", Json::object());
        Json both_substeps;  // on both footings: the equal footing's steps per frame
        for (const Json& b : doc["backends"])
            if (b.contains("label") && b.value("footing", Json::object()).value("kind", "") == "equal")
                both_substeps = b["footing"].value("substeps_per_frame", Json());
        if (!both_substeps.is_null())
            h << "<p><b>Footing: both, side by side</b>: every engine twice, at its own defaults (every departure "
                 "listed as a deviation) and on the equal footing of "
              << cellText(both_substeps)
              << " internal steps per frame with isotropic Coulomb friction where the engine has it; each run is "
                 "labelled with its footing.</p>\n";
        else if (footing.value("kind", "") == "equal")
            h << "<p><b>Footing: equal</b>: " << cellText(footing.value("substeps_per_frame", Json()))
              << " internal steps per frame on every engine, isotropic Coulomb friction where the engine has it "
                 "(the footing's settings per engine below; a --set of the same key wins).</p>\n";
        else
            h << "<p><b>Footing: defaults</b>: each engine at its own defaults; every departure is listed as a "
                 "deviation.</p>\n";
        h << "<table><tr><th>backend</th><th>version</th><th>footing sets</th><th>settings</th></tr>\n";
        for (const Json& b : doc["backends"]) {
            std::string settings, footed;
            const Json values = b.value("settings", Json::object());   // items() must not outlive it
            for (const auto& [k, v] : values.items()) settings += k + "=" + cellText(v) + " ";
            const Json applied = b.value("footing", Json::object()).value("settings", Json::object());
            for (const auto& [k, v] : applied.items()) footed += k + "=" + cellText(v) + " ";
            h << "<tr><td>" << htmlEscaped(b.value("label", b.value("name", ""))) << "</td><td>"
              << htmlEscaped(b.value("version", "")) << "</td><td>" << htmlEscaped(footed.empty() ? "-" : footed)
              << "</td><td>" << htmlEscaped(settings) << "</td></tr>\n";
        }
        h << "</table>\n";
    }
    if (doc.contains("parameters")) h << "<p>Parameters: <code>" << htmlEscaped(doc["parameters"].dump()) << "</code></p>\n";
    h << "<p>Build: <code>" << htmlEscaped(doc.value("build", Json::object()).dump()) << "</code></p>\n"
      << "<p>Command: <code>" << htmlEscaped(doc.value("command_line", "")) << "</code>, written "
      << htmlEscaped(doc.value("created_utc", "")) << "</p>\n";
    return h.str();
}

std::string documentHtml(const Json& doc, const fs::path& chart_dir, std::size_t index) {
    std::ostringstream h;
    h << "<section id=\"doc-" << index << "\">\n<h2>vroc " << htmlEscaped(doc.value("command", "")) << ": "
      << htmlEscaped(doc.value("title", "")) << "</h2>\n";
    if (doc.contains("summary")) h << "<p>" << htmlEscaped(doc["summary"].get<std::string>()) << "</p>\n";
    for (const Json& t : doc["tables"]) h << tableHtml(t);
    for (const Json& chart : doc["charts"]) {
        Json placed = chart;
        std::string id(1, 'd');
        id += std::to_string(index) + "-" + chart["id"].get<std::string>();
        placed["id"] = id;
        h << "<figure class=\"chart\" id=\"chart-" << htmlEscaped(placed["id"]) << "\" data-series=\""
          << chart["series"].size() << "\">\n<figcaption>" << htmlEscaped(chart["title"].get<std::string>())
          << "</figcaption>\n" << renderChart(placed, chart_dir) << "\n</figure>\n";
    }
    h << settingsHtml(doc) << "</section>\n";
    return h.str();
}

}  // namespace

fs::path writeReport(const std::vector<Json>& documents, const fs::path& out_dir) {
    fs::create_directories(out_dir);
    std::ostringstream h;
    h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>VROC report</title>\n<style>" << kStyle
      << "</style></head><body>\n<h1>VROC comparison report</h1>\n";
    // The 3D replay (docs/viewer.md): `vroc compare` and `vroc ensemble` write view.html next to
    // the report (tools/vroc/report_view.cpp); a merged report of several runs has none.
    const std::string command = documents.size() == 1 ? documents[0].value("command", "") : "";
    if (command == "compare" || command == "ensemble")
        h << "<section id=\"replay\">\n<h2>3D replay</h2>\n<p><a href=\"view.html\">view.html</a>: every backend "
             "side by side (or overlaid as ghosts) with a shared time slider; written by <code>vroc view</code>.</p>\n"
             "<iframe src=\"view.html\" title=\"3D replay\" style=\"width:100%;height:560px;border:1px solid #ccc\">"
             "</iframe>\n</section>\n";
    for (std::size_t i = 0; i < documents.size(); ++i) h << documentHtml(documents[i], out_dir / "charts", i);
    h << "</body></html>\n";
    const fs::path path = out_dir / "report.html";
    recording::AtomicFile file(path);
    file.write(h.str());
    file.commit();
    return path;
}

}  // namespace vroc::harness
