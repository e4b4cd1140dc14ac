// SPDX-License-Identifier: MIT
// Reports carry the data: every chart's gnuplot data file and SVG match the series in
// metrics.json; a rendered report is looked at in headless Chromium; `vroc report` rebuilds it.
#include <gtest/gtest.h>
#include <png.h>

#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>

#include "harness_test_backends.h"
#include "subprocess.h"
#include "test_scenes.h"
#include "vroc/core/errors.h"
#include "vroc/core/mass_properties.h"
#include "vroc/core/subprocess.h"
#include "vroc/harness/commands/compare.h"
#include "vroc/harness/commands/report_merge.h"
#include "vroc/harness/documents/compare_document.h"
#include "vroc/harness/documents/html_report.h"

namespace vroc::harness {
namespace {
namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

struct Block {
    std::size_t points = 0;
    double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
};

// Parses a gnuplot data file: "x y" rows, index blocks separated by two blank lines.
std::vector<Block> parseDat(const fs::path& p) {
    std::vector<Block> blocks;
    std::istringstream in(slurp(p));
    std::string line;
    int blanks = 2;
    while (std::getline(in, line)) {
        if (line.empty()) { ++blanks; continue; }
        if (line[0] == '#') continue;
        if (blanks >= 2) blocks.emplace_back();
        blanks = 0;
        double x = 0, y = 0;
        EXPECT_EQ(std::sscanf(line.c_str(), "%lf %lf", &x, &y), 2) << p << ": " << line;
        Block& b = blocks.back();
        ++b.points;
        b.xmin = std::min(b.xmin, x); b.xmax = std::max(b.xmax, x);
        b.ymin = std::min(b.ymin, y); b.ymax = std::max(b.ymax, y);
    }
    return blocks;
}

std::size_t count(const std::string& text, const std::string& word) {
    std::size_t n = 0;
    for (auto pos = text.find(word); pos != std::string::npos; pos = text.find(word, pos + 1)) ++n;
    return n;
}

Json compareDocument() {
    harness_test::registerTestBackends();
    Scene s;
    s.name = "report-flight";
    s.gravity = Vec3(0, 0, -9.81);
    s.frame_dt = 0.01;
    s.materials.push_back({"m", 0.5, 0.5});
    for (int i = 0; i < 2; ++i) {
        Body b;
        b.name = "body" + std::to_string(i);
        b.shape = i ? Shape::box(Vec3(0.1, 0.2, 0.3)) : Shape::sphere(0.1);
        b.mass_properties = massProperties(b.shape, 1.0 + i);
        b.pose.position = Vec3(3.0 * i, 0, 20);
        b.linear_velocity = Vec3(1, 2, 3);
        b.angular_velocity = Vec3(0.1, 0.2, 0.3 * i);
        s.bodies.push_back(b);
    }
    CompareOptions o;
    o.duration = 1.0;
    o.progress = false;
    o.write_csv = false;
    o.windows = 4;
    return compareDocument(compareScene(s, selectBackends("test-exact,test-euler", {}), o, {}), "vroc compare");
}

// Every chart in the document: the data file gnuplot read has the same series, point counts and
// ranges as metrics.json, and the SVG draws one plot group per series.
void expectChartsCarryData(const Json& doc, const fs::path& chart_dir, std::size_t doc_index) {
    ASSERT_FALSE(doc["charts"].empty());
    for (const Json& chart : doc["charts"]) {
        const std::string id = "d" + std::to_string(doc_index) + "-" + chart["id"].get<std::string>();
        const auto blocks = parseDat(chart_dir / (id + ".dat"));
        ASSERT_EQ(blocks.size(), chart["series"].size()) << id;
        for (std::size_t i = 0; i < blocks.size(); ++i) {
            const Json& s = chart["series"][i];
            const auto x = s["x"].get<std::vector<double>>(), y = s["y"].get<std::vector<double>>();
            EXPECT_EQ(blocks[i].points, x.size()) << id << " series " << s["name"];
            EXPECT_EQ(blocks[i].xmin, *std::min_element(x.begin(), x.end())) << id;
            EXPECT_EQ(blocks[i].xmax, *std::max_element(x.begin(), x.end())) << id;
            EXPECT_EQ(blocks[i].ymin, *std::min_element(y.begin(), y.end())) << id;
            EXPECT_EQ(blocks[i].ymax, *std::max_element(y.begin(), y.end())) << id;
        }
        const std::string svg = slurp(chart_dir / (id + ".svg"));
        EXPECT_EQ(count(svg, "id=\"gnuplot_plot_"), chart["series"].size()) << id;
    }
}

TEST(HarnessReport, ChartsCarryTheDataOfMetricsJson) {
    const fs::path dir = test::freshTempDir("harness-report");
    const Json doc = compareDocument();
    writeDocument(doc, dir / "metrics.json");
    const fs::path report = writeReport({doc}, dir);
    ASSERT_TRUE(fs::exists(report));
    expectChartsCarryData(doc, dir / "charts", 0);
    const std::string html = slurp(report);
    EXPECT_EQ(count(html, "<figure class=\"chart\""), doc["charts"].size());
    EXPECT_EQ(html.find("http://www.w3.org/1999/xlink\" xlink:href"), std::string::npos);   // nothing fetched
    EXPECT_EQ(html.find("<script src"), std::string::npos);
    // Summary table first, then charts, then settings.
    EXPECT_LT(html.find("table-summary"), html.find("<figure"));
    EXPECT_LT(html.find("<figure"), html.find("Settings, versions and build"));
    // Every number in the summary table is in metrics.json.
    EXPECT_NE(html.find(cellText(doc["tables"][0]["rows"][0][2])), std::string::npos);
}

TEST(HarnessReport, ReportCommandRebuildsAndMerges) {
    const fs::path a = test::freshTempDir("harness-merge-a"), out = test::freshTempDir("harness-merge-out");
    const Json doc = compareDocument();
    writeDocument(doc, a / "metrics.json");
    const auto path = rebuildReport({a, a}, out);
    const std::string html = slurp(path);
    EXPECT_EQ(count(html, "<section id=\"doc-"), 2u);
    expectChartsCarryData(doc, out / "charts", 1);
    EXPECT_THROW(rebuildReport({out / "missing"}, out), InputError);
}

// Mean of per-channel standard deviations of a PNG: 0 for a blank page.
double pngContrast(const fs::path& path, int& width, int& height) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&image, path.c_str())) return -1;
    image.format = PNG_FORMAT_GRAY;
    std::vector<unsigned char> pixels(PNG_IMAGE_SIZE(image));
    if (!png_image_finish_read(&image, nullptr, pixels.data(), 0, nullptr)) return -1;
    width = static_cast<int>(image.width);
    height = static_cast<int>(image.height);
    double sum = 0, sq = 0;
    for (unsigned char p : pixels) { sum += p; sq += double(p) * p; }
    const double n = static_cast<double>(pixels.size());
    return std::sqrt(std::max(0.0, sq / n - (sum / n) * (sum / n)));
}

TEST(HarnessReport, RendersInHeadlessChromium) {
    const fs::path dir = test::freshTempDir("harness-chromium");
    SpawnOptions quiet;
    quiet.stdout_file = quiet.stderr_file = dir / "chromium-version.log";
    try {
        runProcess({"chromium", "--version"}, quiet);
    } catch (const RunError&) {
        GTEST_SKIP() << "chromium not installed (make deps)";
    }
    const Json doc = compareDocument();
    const fs::path report = writeReport({doc}, dir);
    const fs::path shot = dir / "shot.png", profile = dir / "profile";
    SpawnOptions logged;
    logged.stdout_file = logged.stderr_file = dir / "chromium.log";
    const int status = runProcess({"timeout", "120", "chromium", "--headless", "--no-sandbox", "--disable-gpu",
                                   "--disable-background-networking", "--disable-component-update", "--disable-sync",
                                   "--no-first-run", "--hide-scrollbars", "--user-data-dir=" + profile.string(),
                                   "--window-size=1100,2400", "--screenshot=" + shot.string(),
                                   "file://" + fs::absolute(report).string()},
                                  logged);
    ASSERT_EQ(status, 0) << slurp(dir / "chromium.log");
    ASSERT_TRUE(fs::exists(shot)) << slurp(dir / "chromium.log");
    int w = 0, h = 0;
    const double contrast = pngContrast(shot, w, h);
    EXPECT_EQ(w, 1100);
    EXPECT_EQ(h, 2400);
    EXPECT_GT(contrast, 10.0) << "the screenshot is (nearly) blank: " << shot;
}

}  // namespace
}  // namespace vroc::harness
