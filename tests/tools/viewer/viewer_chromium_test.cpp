// SPDX-License-Identifier: MIT
// The replay page in headless Chromium (Debian's, WebGL by SwiftShader): it loads with no error and
// no network request and holds the run's bodies and frames (counted here from the run's files); its
// pictures change between two times exactly where bodies move; a body's centre, projected with the
// page's own camera, lands on a pixel of that body's colour at three times; the ghosts of two
// identical runs coincide. Skipped only when chromium is not installed.
#include <cmath>
#include <filesystem>

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

// At least 5 of the 9 pixels around (x, y) have the hue of `colour` (within 20 degrees) and are
// clearly coloured: lighting scales a colour's brightness, not its hue.
bool showsColour(const test::Screenshot& shot, double x, double y, const std::string& colour) {
    double want_hue = 0, want_sat = 0;
    test::hueSaturation(test::parseHex(colour), want_hue, want_sat);
    int hits = 0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            double hue = 0, sat = 0;
            test::hueSaturation(shot.at(int(std::lround(x)) + dx, int(std::lround(y)) + dy), hue, sat);
            const double d = std::abs(std::remainder(hue - want_hue, 360.0));
            hits += (d < 20 && sat > 0.3) ? 1 : 0;
        }
    return hits >= 5;
}

TEST(ViewerChromium, LoadsWithoutErrorsOrNetworkAndHoldsTheRun) {
    const fs::path dir = test::freshTempDir("viewer-load");
    SKIP_WITHOUT_CHROMIUM(dir);
    const fs::path run = test::recordViewerRun(dir, "run");
    const fs::path page = writePage(dir, {run}, "view.html");
    const auto self = test::pageSelfTest(page, "", dir);
    ASSERT_TRUE(self) << "no self-test in the page's DOM: " << test::readText((dir / "chromium.log").string());
    EXPECT_TRUE((*self)["ok"].get<bool>()) << self->dump();
    EXPECT_TRUE((*self)["errors"].empty()) << (*self)["errors"].dump();
    EXPECT_EQ((*self)["resources"], 0) << "the page fetched something";
    EXPECT_EQ((*self)["bodies"], test::kViewerSceneBodies);
    const auto lines = test::splitLines(test::readText((run / "trajectory.csv").string()));
    EXPECT_EQ((*self)["frames"].get<std::size_t>(), (lines.size() - 1) / 3);  // 3 moving bodies per frame
    EXPECT_EQ((*self)["backends"], Json::array({"native"}));
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
    const auto self = test::pageSelfTest(page, "#overlay=1&probe=1,3&probe_frames=10,30" + kProbeSize, dir);
    ASSERT_TRUE(self);
    EXPECT_TRUE((*self)["overlay"].get<bool>());
    ASSERT_EQ((*self)["views"].size(), 2u);
    for (int f : {10, 30})
        for (int b : {1, 3}) {
            const Json &a = probe(*self, f, b, 0), &c = probe(*self, f, b, 1);
            EXPECT_NEAR(a["x"].get<double>(), c["x"].get<double>(), 0.5);
            EXPECT_NEAR(a["y"].get<double>(), c["y"].get<double>(), 0.5);
        }
    // Two translucent ghosts in one place show the body's colour at its centre.
    const auto shot = test::screenshot(page, "#overlay=1&events=0&frame=30", dir / "ghosts.png", dir);
    ASSERT_TRUE(shot);
    const Json& p = probe(*self, 30, 1, 0);
    EXPECT_TRUE(showsColour(*shot, p["x"], p["y"], p["colour"])) << p.dump() << " in " << dir / "ghosts.png";
}

}  // namespace
}  // namespace vroc::viewer
