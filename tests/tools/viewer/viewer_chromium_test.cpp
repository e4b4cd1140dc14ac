// SPDX-License-Identifier: MIT
// The replay page in headless Chromium (Debian's, WebGL by SwiftShader): it loads with no error and
// no network request and holds the run's bodies and frames (counted here from the run's files); its
// pictures change between two times exactly where bodies move; a body's centre, projected with the
// page's own camera, lands on a pixel of that body's colour at three times; the ghosts of two
// identical runs coincide; each engine's ghosts, legend entry and label show its own tint. The page
// `vroc run` writes is the one loaded first. Skipped only when chromium is not installed.
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include <gtest/gtest.h>

#include "headless_chromium.h"
#include "viewer_test_runs.h"

namespace vroc::viewer {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

constexpr int kBarHeight = 58;  // [px] page/viewer.css: the control bar above the views
// Chromium's --dump-dom lays the page out in a smaller window than --screenshot does at the same
// --window-size: the self-test projects for the screenshot's window.
const std::string kProbeSize =
    "&probe_size=" + std::to_string(test::kShotWidth) + "x" + std::to_string(test::kShotHeight);

fs::path writePage(const fs::path& dir, const std::vector<fs::path>& runs, const std::string& name) {
    std::vector<std::string> args{"view"};
    for (const fs::path& r : runs) args.push_back(r.string());
    args.insert(args.end(), {"-o", (dir / name).string()});
    const test::ProcessResult r = test::runVroc(args, dir);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return dir / name;
}

#define SKIP_WITHOUT_CHROMIUM(dir) \
    if (!test::haveChromium(dir)) GTEST_SKIP() << "chromium not installed (make deps)"

// The probe of `body` in `view` at `frame` from the self-test.
const Json& probe(const Json& self, int frame, int body, int view) {
    for (const Json& p : self["probes"])
        if (p["frame"] == frame && p["body"] == body && p["view"] == view) return p;
    throw std::runtime_error("no probe for frame " + std::to_string(frame) + " body " + std::to_string(body));
}

// At least 5 of the 9 pixels around a point have the hue of `colour` (within 20 degrees) and are
// clearly coloured: lighting scales a colour's brightness, not its hue.
bool showsColour(const std::vector<test::Rgb>& pixels, const std::string& colour) {
    double want_hue = 0, want_sat = 0;
    test::hueSaturation(test::parseHex(colour), want_hue, want_sat);
    int hits = 0;
    for (const test::Rgb& pixel : pixels) {
        double hue = 0, sat = 0;
        test::hueSaturation(pixel, hue, sat);
        const double d = std::abs(std::remainder(hue - want_hue, 360.0));
        hits += (d < 20 && sat > 0.3) ? 1 : 0;
    }
    return hits >= 5;
}

// ... around (x, y) of a screenshot.
bool showsColour(const test::Screenshot& shot, double x, double y, const std::string& colour) {
    std::vector<test::Rgb> pixels;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) pixels.push_back(shot.at(int(std::lround(x)) + dx, int(std::lround(y)) + dy));
    return showsColour(pixels, colour);
}

// ... around a probe at the frame the page drew, as the page read them back from its canvas.
bool showsColour(const Json& probe, const std::string& colour) {
    std::vector<test::Rgb> pixels;
    for (const Json& hex : probe.value("pixels", Json::array())) pixels.push_back(test::parseHex(hex));
    return pixels.size() == 9 && showsColour(pixels, colour);
}

// The page is the one `vroc run` wrote into its directory (the same as `vroc view --no-penetration`
// writes of it, and a note: ViewerInputs.RunWritesTheViewThatViewWrites).
TEST(ViewerChromium, LoadsWithoutErrorsOrNetworkAndHoldsTheRun) {
    const fs::path dir = test::freshTempDir("viewer-load");
    SKIP_WITHOUT_CHROMIUM(dir);
    const fs::path run = test::recordViewerRun(dir, "run");
    const fs::path page = run / "view.html";
    const auto self = test::pageSelfTest(page, "", dir);
    ASSERT_TRUE(self) << "no self-test in the page's DOM: " << test::readText((dir / "chromium.log").string());
    EXPECT_TRUE((*self)["ok"].get<bool>()) << self->dump();
    EXPECT_TRUE((*self)["errors"].empty()) << (*self)["errors"].dump();
    EXPECT_EQ((*self)["resources"], 0) << "the page fetched something";
    EXPECT_EQ((*self)["bodies"], test::kViewerSceneBodies);
    const auto lines = test::splitLines(test::readText((run / "trajectory.csv").string()));
    EXPECT_EQ((*self)["frames"].get<std::size_t>(), (lines.size() - 1) / 3);  // 3 moving bodies per frame
    EXPECT_EQ((*self)["backends"], Json::array({"native"}));
    ASSERT_EQ((*self)["legend"].size(), 1u);  // one engine, with its tint
    EXPECT_EQ((*self)["legend"][0]["label"], "native");
    EXPECT_EQ((*self)["legend"][0]["tint"], test::pageData(page)["runs"][0]["tint"]);
    std::printf("self-test load time: %d ms (performance.now() at the end of the viewer's script)\n",
                (*self)["load_ms"].get<int>());
}

TEST(ViewerChromium, PicturesChangeWhereBodiesMoveAndBodiesShowTheirColour) {
    const fs::path dir = test::freshTempDir("viewer-pixels");
    SKIP_WITHOUT_CHROMIUM(dir);
    const fs::path run = test::recordViewerRun(dir, "run");
    const fs::path page = writePage(dir, {run}, "view.html");
    const int frames[3] = {5, 20, 40};
    // Bodies 1 (thrown), 2 (resting), 3 (glider, tracked); contact markers off so only bodies move.
    const auto self = test::pageSelfTest(page, "#events=0&probe=1,2,3&probe_frames=5,20,40" + kProbeSize, dir);
    ASSERT_TRUE(self);
    std::vector<test::Screenshot> shots;
    for (int f : frames) {
        const auto shot = test::screenshot(page, "#events=0&frame=" + std::to_string(f),
                                           dir / ("frame" + std::to_string(f) + ".png"), dir);
        ASSERT_TRUE(shot) << test::readText((dir / "chromium.log").string());
        ASSERT_EQ(shot->width, test::kShotWidth);
        shots.push_back(*shot);
    }
    // The thrown ball (body 1) lands on its own colour at every time.
    for (int i = 0; i < 3; ++i) {
        const Json& p = probe(*self, frames[i], 1, 0);
        EXPECT_TRUE(showsColour(shots[i], p["x"], p["y"], p["colour"]))
            << "frame " << frames[i] << ": " << p.dump() << " in "
            << dir / ("frame" + std::to_string(frames[i]) + ".png");
    }
    // Between frames 5 and 40 the picture changes, and only near the moving bodies (thrown ball,
    // tracked glider) at either time; the resting ball's pixels stay as they were.
    const double reach = 70;  // [px] a body's projected size with margin, at this window size
    auto nearMoving = [&](int x, int y) {
        for (int f : {5, 40})
            for (int b : {1, 3}) {
                const Json& p = probe(*self, f, b, 0);
                if (std::hypot(x - p["x"].get<double>(), y - p["y"].get<double>()) < reach) return true;
            }
        return false;
    };
    const Json& resting = probe(*self, 5, 2, 0);
    int changed = 0, stray = 0, near_resting = 0;
    for (int y = kBarHeight; y < shots[0].height; ++y)
        for (int x = 0; x < shots[0].width; ++x) {
            const test::Rgb a = shots[0].at(x, y), b = shots[2].at(x, y);
            if (std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b) < 30) continue;
            ++changed;
            stray += nearMoving(x, y) ? 0 : 1;
            near_resting += std::hypot(x - resting["x"].get<double>(), y - resting["y"].get<double>()) < 10 ? 1 : 0;
        }
    EXPECT_GT(changed, 200) << "frames 5 and 40 look the same";
    EXPECT_EQ(stray, 0) << "pixels changed away from the moving bodies";
    EXPECT_EQ(near_resting, 0) << "the resting ball's pixels changed";
}

TEST(ViewerChromium, GhostsOfTwoIdenticalRunsCoincide) {
    const fs::path dir = test::freshTempDir("viewer-ghosts");
    SKIP_WITHOUT_CHROMIUM(dir);
    const fs::path run = test::recordViewerRun(dir, "run");
    fs::copy(run, dir / "copy", fs::copy_options::recursive);
    const fs::path page = writePage(dir, {run, dir / "copy"}, "ghosts.html");
    const auto self =
        test::pageSelfTest(page, "#overlay=1&events=0&colour=distance&frame=30&probe=1,3&probe_frames=10,30", dir);
    ASSERT_TRUE(self);
    EXPECT_TRUE((*self)["overlay"].get<bool>());
    ASSERT_EQ((*self)["views"].size(), 2u);
    for (int f : {10, 30})
        for (int b : {1, 3}) {
            const Json &a = probe(*self, f, b, 0), &c = probe(*self, f, b, 1);
            EXPECT_NEAR(a["x"].get<double>(), c["x"].get<double>(), 0.5);
            EXPECT_NEAR(a["y"].get<double>(), c["y"].get<double>(), 0.5);
        }
    // Two translucent ghosts in one place, coloured by their distance from the first (zero: both
    // the same colour; by body each would show its engine's tint), show that colour at the centre
    // (the pixels the page drew there, read back from its canvas).
    const Json& p = probe(*self, 30, 1, 0);
    EXPECT_EQ(p["colour"], probe(*self, 30, 1, 1)["colour"]);
    EXPECT_TRUE(showsColour(p, p["colour"])) << p.dump();
}

// Two engines overlaid as ghosts: native, and Bullet on the scene with the thrown ball started 0.6 m
// further along x (shown with the first scene's geometry, --scene), so the two ghosts of the ball
// are apart. The page's data gives each engine one tint and the two differ; the legend and the
// label show each engine with its tint; each ghost of the ball is drawn in its engine's tint.
TEST(ViewerChromium, GhostsLegendAndLabelsShowEachEnginesTint) {
    const fs::path dir = test::freshTempDir("viewer-tints");
    SKIP_WITHOUT_CHROMIUM(dir);
    const fs::path native = test::recordViewerRun(dir, "native", 0.5, "native", {"--no-view"});
    std::string moved = test::kViewerScene;
    const std::string start = "\"position\": [-1.0, 0.0, 0.8]";
    ASSERT_NE(moved.find(start), std::string::npos);
    moved.replace(moved.find(start), start.size(), "\"position\": [-0.4, 0.0, 0.8]");
    const fs::path moved_scene = test::writeFile(dir / "moved.json", moved);
    const test::ProcessResult run = test::runVroc({"run", moved_scene.string(), "--backend", "bullet", "--duration",
                                                   "0.5", "--no-view", "-o", (dir / "bullet").string()},
                                                  dir);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const fs::path page = dir / "tints.html";
    const test::ProcessResult view = test::runVroc({"view", native.string(), (dir / "bullet").string(), "--scene",
                                                    (dir / "viewer_test.json").string(), "-o", page.string()},
                                                   dir);
    ASSERT_EQ(view.exit_code, 0) << view.err;

    // The data: one tint per engine, and distinct.
    std::map<std::string, std::set<std::string>> tints;
    const Json data = test::pageData(page);
    for (const Json& r : data["runs"]) tints[r["label"]].insert(r["tint"].get<std::string>());
    ASSERT_EQ(tints.size(), 2u);
    ASSERT_EQ(tints["native"].size(), 1u);
    ASSERT_EQ(tints["bullet"].size(), 1u);
    const std::string native_tint = *tints["native"].begin(), bullet_tint = *tints["bullet"].begin();
    EXPECT_NE(native_tint, bullet_tint);

    // The page: legend and label entries as drawn (swatch colours read back from the DOM).
    const int frame = 15;  // t = 0.3 s: both balls in flight, 0.6 m apart
    const std::string at = std::to_string(frame);
    const auto self = test::pageSelfTest(page, "#overlay=1&events=0&frame=" + at + "&probe=1&probe_frames=" + at, dir);
    ASSERT_TRUE(self);
    EXPECT_TRUE((*self)["errors"].empty()) << (*self)["errors"].dump();
    const Json engines =
        Json::array({{{"label", "native"}, {"tint", native_tint}}, {{"label", "bullet"}, {"tint", bullet_tint}}});
    EXPECT_EQ((*self)["engines"], engines);
    EXPECT_EQ((*self)["legend"], engines) << "the legend's entries";
    EXPECT_EQ((*self)["labels"], engines) << "the overlay's label";

    // The picture: each ghost of the thrown ball shows its engine's tint at its centre (the pixels
    // the page drew there, read back from its canvas).
    const Json &a = probe(*self, frame, 1, 0), &b = probe(*self, frame, 1, 1);
    EXPECT_EQ(a["colour"], native_tint);
    EXPECT_EQ(b["colour"], bullet_tint);
    ASSERT_GT(std::hypot(a["x"].get<double>() - b["x"].get<double>(), a["y"].get<double>() - b["y"].get<double>()), 40)
        << "the two ghosts overlap: " << a.dump() << " " << b.dump();
    EXPECT_TRUE(showsColour(a, native_tint)) << a.dump();
    EXPECT_TRUE(showsColour(b, bullet_tint)) << b.dump();
}

}  // namespace
}  // namespace vroc::viewer
