// SPDX-License-Identifier: MIT
// The viewer's data against the run's own files, counted here independently (lines of
// trajectory.csv, bodies of the scene file); `vroc view` errors on a missing or truncated
// trajectory; subsampling; each engine's tint; the view `vroc run` writes; a compare on both
// footings; the size of a 200-body, 300-frame, 4-backend page.
#include "vroc/viewer/viewer_inputs.h"

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "base64.h"
#include "viewer_test_runs.h"
#include "vroc/core/errors.h"
#include "vroc/viewer/viewer_page.h"

namespace vroc::viewer {
namespace {

namespace fs = std::filesystem;

// Frames in trajectory.csv, counted from its lines: (rows - header) / moving bodies.
std::size_t framesInFile(const fs::path& trajectory, std::size_t moving) {
    const auto lines = test::splitLines(test::readText(trajectory.string()));
    return (lines.size() - 1) / moving;
}

TEST(ViewerInputs, HoldsTheRunsBodiesAndFrames) {
    const fs::path dir = test::freshTempDir("viewer-inputs");
    const fs::path run = test::recordViewerRun(dir, "run");
    const ViewerData data = loadViewerData({run});
    const auto scene = nlohmann::json::parse(test::readText((dir / "viewer_test.json").string()));
    EXPECT_EQ(data.bodies.size(), scene["bodies"].size());
    EXPECT_EQ(data.moving_bodies, 3u);  // thrown, resting, glider (real floor excluded)
    EXPECT_EQ(data.times.size(), framesInFile(run / "trajectory.csv", 3));
    EXPECT_EQ(data.times.size(), 51u);  // 1 s at 0.02 s, and the start
    ASSERT_EQ(data.runs.size(), 1u);
    EXPECT_EQ(data.runs[0].backend, "native");
    EXPECT_TRUE(data.notes.empty());
    // The first row of the file, parsed here: thrown ball at its start position.
    const auto row = test::splitCsv(test::splitLines(test::readText((run / "trajectory.csv").string()))[1]);
    EXPECT_EQ(row[1], "thrown");
    EXPECT_DOUBLE_EQ(data.runs[0].poses[0][0].position.x(), std::stod(row[2]));
}

TEST(ViewerInputs, SubsamplesLongRunsWithANote) {
    const fs::path dir = test::freshTempDir("viewer-subsample");
    const fs::path run = test::recordViewerRun(dir, "run");
    ViewerOptions options;
    options.max_frames = 10;
    const ViewerData data = loadViewerData({run}, options);
    EXPECT_LE(data.times.size(), 11u);
    EXPECT_GT(data.stride, 1u);
    EXPECT_DOUBLE_EQ(data.times.back(), 1.0);  // the last frame is always kept
    ASSERT_EQ(data.notes.size(), 1u);
    EXPECT_NE(data.notes[0].find("subsampled"), std::string::npos);
}

// A missing or cut trajectory: exit 2, a message naming the file, and no page left behind.
void expectViewFails(const fs::path& dir, const fs::path& run, const std::string& expected) {
    const fs::path out = dir / "view.html";
    const test::ProcessResult r = test::runVroc({"view", run.string(), "-o", out.string()}, dir);
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find((run / "trajectory.csv").string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
    EXPECT_FALSE(fs::exists(dir / "view.html.tmp"));
}

TEST(ViewerInputs, MissingOrTruncatedTrajectoryIsAnInputError) {
    const fs::path dir = test::freshTempDir("viewer-bad");
    const fs::path run = test::recordViewerRun(dir, "run");
    const std::string text = test::readText((run / "trajectory.csv").string());
    std::ofstream(run / "trajectory.csv", std::ios::trunc) << text.substr(0, text.size() * 2 / 3);  // cut mid-row
    expectViewFails(dir, run, "truncated");
    const auto lines = test::splitLines(text);  // whole rows, but only the first 10 frames
    std::ofstream cut(run / "trajectory.csv", std::ios::trunc);
    for (std::size_t i = 0; i < 1 + 3 * 10; ++i) cut << lines[i] << '\n';
    cut.close();
    expectViewFails(dir, run, "holds 10 frames, expected 51");
    fs::remove(run / "trajectory.csv");
    expectViewFails(dir, run, "missing");
}

TEST(ViewerInputs, ViewWritesThePage) {
    const fs::path dir = test::freshTempDir("viewer-cli");
    const fs::path run = test::recordViewerRun(dir, "run");
    const test::ProcessResult r = test::runVroc({"view", run.string(), "-o", (dir / "view.html").string()}, dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string html = test::readText((dir / "view.html").string());
    EXPECT_NE(html.find("default-src 'none'"), std::string::npos);
    EXPECT_EQ(html.find("<script src"), std::string::npos);
    EXPECT_NE(html.find("\"format\":\"vroc-view/1\""), std::string::npos);
}

// Every engine has one tint, "#rrggbb", no two engines share one (up to 7), and the tints go by the
// engines' order in the inputs: the same inputs in another order give the first engine the first
// tint again; an eighth engine is noted.
TEST(ViewerInputs, EachEngineHasItsOwnTintInTheInputsOrder) {
    const fs::path dir = test::freshTempDir("viewer-tints");
    const fs::path native = test::recordViewerRun(dir, "native", 0.2, "native", {"--no-view"});
    const fs::path bullet = test::recordViewerRun(dir, "bullet", 0.2, "bullet", {"--no-view"});
    ViewerOptions options;
    options.penetration = false;
    const ViewerData a = loadViewerData({native, bullet, native}, options);
    ASSERT_EQ(a.runs.size(), 3u);
    EXPECT_EQ(a.runs[2].label, "native (2)");  // a second engine, not the first one again
    std::set<std::string> tints;
    for (const ViewerRun& r : a.runs) {
        EXPECT_TRUE(std::regex_match(r.tint, std::regex("#[0-9a-f]{6}"))) << r.label << ": " << r.tint;
        tints.insert(r.tint);
    }
    EXPECT_EQ(tints.size(), 3u) << "engines share a tint";
    const ViewerData b = loadViewerData({bullet, native}, options);
    ASSERT_EQ(b.runs.size(), 2u);
    EXPECT_EQ(b.runs[0].backend, "bullet");
    EXPECT_EQ(b.runs[0].tint, a.runs[0].tint) << "the first engine's tint follows the order";
    EXPECT_EQ(b.runs[1].tint, a.runs[1].tint);
    EXPECT_EQ(loadViewerData({native, bullet, native}, options).runs[2].tint, a.runs[2].tint);
    EXPECT_TRUE(a.notes.empty()) << a.notes.front();
    // Eight engines: seven tints, the eighth repeats one, and the page says so.
    const ViewerData eight = loadViewerData(std::vector<fs::path>(8, native), options);
    tints.clear();
    for (const ViewerRun& r : eight.runs) tints.insert(r.tint);
    EXPECT_EQ(tints.size(), 7u);
    ASSERT_EQ(eight.notes.size(), 1u);
    EXPECT_NE(eight.notes[0].find("tints repeat"), std::string::npos) << eight.notes[0];
}

// `vroc run -o DIR` writes DIR/view.html and says so; it holds what `vroc view --no-penetration DIR`
// writes (the page ViewerChromium.LoadsWithoutErrorsOrNetworkAndHoldsTheRun loads), and a note that
// the highlight was skipped. --view-penetration writes what `vroc view DIR` writes, highlight
// included. --no-view writes none; --help tells of all three.
TEST(ViewerInputs, RunWritesTheViewThatViewWrites) {
    const fs::path dir = test::freshTempDir("viewer-run-view");
    const auto scene = test::writeFile(dir / "viewer_test.json", test::kViewerScene);
    const test::ProcessResult r =
        test::runVroc({"run", scene.string(), "--backend", "native", "--duration", "1", "-o", "run"}, dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    ASSERT_TRUE(fs::exists(dir / "run" / "view.html")) << r.out << r.err;
    EXPECT_NE(r.out.find("3D view run/view.html"), std::string::npos) << r.out;
    const test::ProcessResult v = test::runVroc({"view", "run", "--no-penetration", "-o", "view.html"}, dir);
    ASSERT_EQ(v.exit_code, 0) << v.err;
    nlohmann::json own = test::pageData(dir / "run" / "view.html");
    ASSERT_EQ(own["notes"].size(), 1u) << own["notes"];
    EXPECT_NE(own["notes"][0].get<std::string>().find("penetration not highlighted"), std::string::npos);
    EXPECT_NE(own["notes"][0].get<std::string>().find("--view-penetration"), std::string::npos);
    own["notes"] = nlohmann::json::array();
    EXPECT_EQ(own, test::pageData(dir / "view.html"));
    ASSERT_EQ(own["runs"].size(), 1u);
    EXPECT_FALSE(own["runs"][0]["has_penetration"].get<bool>());
    EXPECT_EQ(own["times"].size(), framesInFile(dir / "run" / "trajectory.csv", 3));

    const test::ProcessResult p = test::runVroc(
        {"run", scene.string(), "--backend", "native", "--duration", "0.3", "--view-penetration", "-o", "pen"}, dir);
    ASSERT_EQ(p.exit_code, 0) << p.err;
    ASSERT_EQ(test::runVroc({"view", "pen", "-o", "pen.html"}, dir).exit_code, 0);
    const nlohmann::json judged = test::pageData(dir / "pen" / "view.html");
    EXPECT_EQ(judged, test::pageData(dir / "pen.html"));
    EXPECT_TRUE(judged["runs"][0]["has_penetration"].get<bool>());

    const test::ProcessResult bare = test::runVroc(
        {"run", scene.string(), "--backend", "native", "--duration", "0.1", "--no-view", "-o", "bare"}, dir);
    ASSERT_EQ(bare.exit_code, 0) << bare.err;
    EXPECT_TRUE(fs::exists(dir / "bare" / "run.json"));
    EXPECT_FALSE(fs::exists(dir / "bare" / "view.html"));
    EXPECT_EQ(bare.out.find("view.html"), std::string::npos) << bare.out;
    const test::ProcessResult help = test::runVroc({"run", "--help"}, dir);
    EXPECT_NE(help.out.find("--no-view"), std::string::npos) << help.out;
    EXPECT_NE(help.out.find("--view-penetration"), std::string::npos) << help.out;
    EXPECT_NE(help.out.find("view.html"), std::string::npos) << help.out;
}

// The last recorded position of `body` in a trajectory.csv, parsed here.
Vec3 lastPosition(const fs::path& trajectory, const std::string& body) {
    const auto lines = test::splitLines(test::readText(trajectory.string()));
    for (auto line = lines.rbegin(); line != lines.rend(); ++line) {
        const auto row = test::splitCsv(*line);
        if (row.size() > 4 && row[1] == body) return {std::stod(row[2]), std::stod(row[3]), std::stod(row[4])};
    }
    ADD_FAILURE() << trajectory << ": no row of " << body;
    return Vec3::Zero();
}

// `vroc compare --footing both` runs every backend twice and keeps each run's CSVs under its key
// (native-defaults/, bullet-equal/, ...): the page shows all four runs as four engines, each named
// by its footing, with four tints, and each with the poses of its own folder (Bullet's two
// footings fly the thrown ball apart: 1 vs 4 internal steps per frame).
TEST(ViewerInputs, CompareOnBothFootingsShowsEachFootingAsItsOwnEngine) {
    const fs::path dir = test::freshTempDir("viewer-footing-both");
    const auto scene = test::writeFile(dir / "viewer_test.json", test::kViewerScene);
    const test::ProcessResult r =
        test::runVroc({"compare", scene.string(), "--backends", "native,bullet", "--footing", "both", "--duration",
                       "0.3", "--windows", "1", "--window", "0.1", "--jobs", "1", "-q", "-o", "both"},
                      dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find("no 3D view"), std::string::npos) << r.err;
    ASSERT_TRUE(fs::exists(dir / "both" / "view.html"));
    // Each run's label and the folder of its CSVs.
    const std::vector<std::pair<std::string, std::string>> expected = {{"native (own defaults)", "native-defaults"},
                                                                       {"native (equal footing)", "native-equal"},
                                                                       {"bullet (own defaults)", "bullet-defaults"},
                                                                       {"bullet (equal footing)", "bullet-equal"}};
    ViewerOptions options;
    options.penetration = false;
    const ViewerData data = loadViewerData({dir / "both"}, options);
    ASSERT_EQ(data.runs.size(), expected.size());
    std::set<std::string> tints;
    for (std::size_t i = 0; i < expected.size(); ++i) {
        const ViewerRun& run = data.runs[i];
        EXPECT_EQ(run.label, expected[i].first);
        EXPECT_EQ(run.backend, expected[i].second.substr(0, expected[i].second.find('-')));
        const Vec3 file = lastPosition(dir / "both" / expected[i].second / "trajectory.csv", "thrown");
        EXPECT_LT((run.poses.back()[0].position - file).norm(), 1e-12) << run.label << " vs " << expected[i].second;
        tints.insert(run.tint);
    }
    EXPECT_EQ(tints.size(), expected.size()) << "two footings share a tint";
    EXPECT_GT((data.runs[2].poses.back()[0].position - data.runs[3].poses.back()[0].position).norm(), 1e-3)
        << "Bullet's two footings should fly apart (else a swapped folder would go unseen)";
    // The page `vroc compare` wrote shows the same four engines.
    const nlohmann::json page = test::pageData(dir / "both" / "view.html");
    ASSERT_EQ(page["runs"].size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(page["runs"][i]["label"], expected[i].first);
}

TEST(ViewerInputs, Base64MatchesRfc4648) {
    EXPECT_EQ(base64(""), "");
    EXPECT_EQ(base64("f"), "Zg==");
    EXPECT_EQ(base64("fo"), "Zm8=");
    EXPECT_EQ(base64("foobar"), "Zm9vYmFy");  // RFC 4648, section 10
    std::string bytes;
    appendFloat32(bytes, 1.0f);  // 0x3f800000, little-endian
    EXPECT_EQ(bytes, std::string("\x00\x00\x80\x3f", 4));
}

// An ensemble keeps no trajectories: `vroc view` replays its members, and each replay ends in the
// state the ensemble recorded for that member (runs/member-<backend>-<m>.json), else the page says so.
TEST(ViewerInputs, EnsembleMembersAreReplayedToTheirRecordedStates) {
    const fs::path dir = test::freshTempDir("viewer-ensemble");
    const auto scene = test::writeFile(dir / "viewer_test.json", test::kViewerScene);
    const test::ProcessResult r = test::runVroc(
        {"ensemble", scene.string(), "--backends", "native,bullet", "--members", "3", "--duration", "0.5", "--perturb",
         "positions=0.01", "--permutations", "99", "--no-view", "-o", (dir / "ens").string()},
        dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::vector<std::string> view{"view", (dir / "ens").string(),   "--members", "2",
                                        "-o",   (dir / "v.html").string()};
    const test::ProcessResult v = test::runVroc(view, dir);
    ASSERT_EQ(v.exit_code, 0) << v.err;
    const auto data = test::pageData(dir / "v.html");
    ASSERT_EQ(data["runs"].size(), 4u);  // 2 of 3 members x 2 backends
    int medians = 0;
    for (const auto& run : data["runs"]) medians += run["median"].get<bool>() ? 1 : 0;
    EXPECT_EQ(medians, 2);                                 // one per backend
    std::map<std::string, std::set<std::string>> tints;    // backend -> its members' tints
    for (const auto& run : data["runs"]) tints[run["backend"]].insert(run["tint"].get<std::string>());
    ASSERT_EQ(tints.size(), 2u);
    EXPECT_EQ(tints["native"].size(), 1u) << "an ensemble's members share their engine's tint";
    EXPECT_EQ(tints["bullet"].size(), 1u);
    EXPECT_NE(*tints["native"].begin(), *tints["bullet"].begin());
    ASSERT_EQ(data["notes"].size(), 1u) << data["notes"];  // "2 of 3 members", and no mismatch
    EXPECT_NE(data["notes"][0].get<std::string>().find("2 of 3 members"), std::string::npos);
    // A recorded hash that does not match is named on the page.
    const fs::path member = dir / "ens" / "runs" / "member-bullet-1.json";
    std::string text = test::readText(member.string());
    const std::size_t at = text.find("\"state_hash\"");
    ASSERT_NE(at, std::string::npos);
    text.replace(text.find('"', text.find(':', at)) + 1, 16, "0123456789abcdef");
    std::ofstream(member, std::ios::trunc) << text;
    ASSERT_EQ(test::runVroc(view, dir).exit_code, 0);
    const auto changed = test::pageData(dir / "v.html");
    ASSERT_EQ(changed["notes"].size(), 2u);
    EXPECT_NE(changed["notes"][0].get<std::string>().find("bullet #1"), std::string::npos) << changed["notes"];
}

// 200 boxes x 300 frames x 4 backends stays under 10 MB (issue 25), without subsampling.
TEST(ViewerPage, TwoHundredBodiesThreeHundredFramesFourBackendsUnderTenMegabytes) {
    ViewerData data;
    data.title = "size";
    for (int b = 0; b < 200; ++b) {
        ViewerBody body;
        body.name = "box_" + std::to_string(b);
        body.moving_index = b;
        ViewerPart part;
        part.kind = ViewerPart::Kind::Box;
        part.half_extents = Vec3(0.05, 0.05, 0.05);
        body.parts.push_back(part);
        data.bodies.push_back(body);
    }
    data.moving_bodies = 200;
    for (int f = 0; f < 300; ++f) data.times.push_back(f / 60.0);
    for (const char* backend : {"native", "bullet", "ode", "mujoco"}) {
        ViewerRun run;
        run.backend = run.label = backend;
        for (int f = 0; f < 300; ++f) {
            run.poses.emplace_back();
            for (int b = 0; b < 200; ++b)
                run.poses.back().push_back({Vec3(0.1 * b, 0.01 * f, 1.0 / (1 + f)),
                                            Quat(Eigen::AngleAxisd(0.01 * f * b, Vec3(0.3, 0.4, 0.5).normalized()))});
            run.penetrating.emplace_back(200, false);
        }
        data.runs.push_back(run);
    }
    const std::size_t bytes = viewerPageHtml(data).size();
    EXPECT_LT(bytes, 10'000'000u);
    // ... and selectFrames would not subsample it (6 MiB of packed poses).
    EXPECT_LE(200u * 300u * 4u * 24u, ViewerOptions{}.max_pose_bytes);
    std::printf("page for 200 bodies x 300 frames x 4 backends: %.2f MB\n", double(bytes) / 1e6);
}

}  // namespace
}  // namespace vroc::viewer
