// SPDX-License-Identifier: MIT
#include "vroc/harness/documents/gnuplot_chart.h"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "vroc/core/errors.h"
#include "vroc/core/subprocess.h"

namespace vroc::harness {
namespace fs = std::filesystem;

std::string gnuplotQuoted(const std::string& text) {
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        if (c == '\n') { out += ' '; continue; }
        out += c;
    }
    return out + "\"";
}

namespace {

void writeText(const fs::path& path, const std::string& text) {
    std::ofstream out(path);
    out << text;
    if (!out) throw RunError(path.string() + ": cannot write");
}

std::string dataFile(const Json& chart) {
    std::string text;
    char line[96];
    for (const Json& s : chart["series"]) {
        text += "# " + s["name"].get<std::string>() + "\n";
        const auto& x = s["x"];
        const auto& y = s["y"];
        for (std::size_t i = 0; i < x.size(); ++i) {
            std::snprintf(line, sizeof line, "%.17g %.17g\n", x[i].get<double>(), y[i].get<double>());
            text += line;
        }
        text += "\n\n";   // two blank lines end a gnuplot index block
    }
    return text;
}

std::string script(const Json& chart, const fs::path& dat, const fs::path& svg) {
    std::ostringstream gp;
    gp << "set terminal svg size 860,420 dynamic font 'sans,11' background rgb 'white'\n"
       << "set output " << gnuplotQuoted(svg.string()) << "\n"
       << "set title " << gnuplotQuoted(chart["title"]) << " noenhanced\n"
       << "set xlabel " << gnuplotQuoted(chart["xlabel"]) << " noenhanced\n"
       << "set ylabel " << gnuplotQuoted(chart["ylabel"]) << " noenhanced\n"
       << "set grid\nset key outside right top noenhanced\nset style fill solid 0.5 border\n";
    if (chart["logx"].get<bool>()) gp << "set logscale x\nset format x '%.0e'\n";
    if (chart["logy"].get<bool>()) gp << "set logscale y\nset format y '%.0e'\n";
    gp << "plot ";
    int index = 0;
    for (const Json& s : chart["series"]) {
        const std::string style = s["style"];
        std::string with = style == "linespoints" ? "linespoints pt 7 ps 0.8" : style == "points" ? "points pt 7 ps 0.7" : style;
        if (style == "linespoints" && s["name"] == "Pareto front") with = "linespoints lw 2 lc rgb 'black' dt 2 pt 6 ps 1.6";
        gp << (index ? ", \\\n     " : "") << gnuplotQuoted(dat.string()) << " index " << index
           << " using 1:2 with " << with << " title " << gnuplotQuoted(s["name"]);
        ++index;
    }
    gp << "\n";
    return gp.str();
}

}  // namespace

std::string renderChart(const Json& chart, const fs::path& dir) {
    fs::create_directories(dir);
    const std::string id = chart["id"];
    const fs::path dat = dir / (id + ".dat"), gp = dir / (id + ".gp"), svg = dir / (id + ".svg"), log = dir / (id + ".log");
    writeText(dat, dataFile(chart));
    if (chart["series"].empty()) return "<p class=\"nodata\">no data to plot</p>";
    writeText(gp, script(chart, dat, svg));
    SpawnOptions options;
    options.stderr_file = log;
    int status = 0;
    try {
        status = runProcess({"gnuplot", gp.string()}, options);
    } catch (const RunError& e) {
        throw RunError(std::string(e.what()) + " (is gnuplot-nox installed?)");
    }
    if (status != 0)
        throw RunError("gnuplot failed on " + gp.string() + " (see " + log.string() + "; is gnuplot-nox installed?)");
    std::ifstream in(svg);
    std::stringstream text;
    text << in.rdbuf();
    std::string s = text.str();
    const auto start = s.find("<svg");
    if (start == std::string::npos) throw RunError(svg.string() + ": gnuplot wrote no SVG");
    return s.substr(start);
}

}  // namespace vroc::harness
