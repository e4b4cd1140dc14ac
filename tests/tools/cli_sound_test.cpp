// SPDX-License-Identifier: MIT
// `vroc run --sound` and `vroc play --sound` as a user runs them (docs/hmd.md#impact-sound): the
// WAV and its events CSV appear next to each other, run.json names them, the output stage is said,
// one CSV row per event of events.csv; bad options are exit 2 before anything is simulated.
#include <filesystem>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "csv_reader.h"
#include "subprocess.h"
#include "test_scenes.h"

namespace vroc::test {
namespace {
namespace fs = std::filesystem;

const std::string kBallDrop = std::string(VROC_SOURCE_DIR) + "/scenes/ball_drop.json";

TEST(CliSound, RunWritesTheWavAndNamesItInRunJson) {
    const fs::path dir = freshTempDir("cli-sound-run");
    const auto r = runVroc({"run", kBallDrop, "-b", "native", "--duration", "2", "--out", "out", "--sound",
                            "sound/drop.wav", "--sound-level", "fixed"}, dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("fixed level"), std::string::npos) << r.out;
    EXPECT_TRUE(fs::exists(dir / "sound" / "drop.wav"));
    const auto csv = splitLines(readText((dir / "sound" / "drop_events.csv").string()));
    const auto events = splitLines(readText((dir / "out" / "events.csv").string()));
    ASSERT_FALSE(csv.empty());
    EXPECT_EQ(csv[0], "t,body_a,body_b,impulse,threshold,sample,status");
    EXPECT_EQ(csv.size(), events.size());   // one row per event, same header count
    for (std::size_t k = 1; k < csv.size(); ++k)
        EXPECT_EQ(splitCsv(csv[k])[0], splitCsv(events[k])[0]) << "row " << k << ": same event time";
    const auto j = nlohmann::json::parse(readText((dir / "out" / "run.json").string()));
    EXPECT_EQ(j["outputs"]["sound"]["file"], "sound/drop.wav");
    EXPECT_NE(j["outputs"]["sound"]["description"].get<std::string>().find("48000 Hz"), std::string::npos);
    EXPECT_EQ(j["outputs"]["sound_events"]["file"], "sound/drop_events.csv");
    fs::remove_all(dir);
}

TEST(CliSound, BadOptionsAreExitTwoBeforeTheRun) {
    const fs::path dir = freshTempDir("cli-sound-bad");
    auto r = runVroc({"run", kBallDrop, "-b", "native", "--out", "out", "--sound", "s.wav", "--sound-level", "loud"},
                     dir);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--sound-level"), std::string::npos) << r.err;
    r = runVroc({"run", kBallDrop, "-b", "native", "--out", "out", "--sound", "/proc/vroc-no/s.wav"}, dir);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--sound '/proc/vroc-no/s.wav'"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "out"));
    r = runVroc({"run", kBallDrop, "-b", "native", "--out", "out", "--duration", "700", "--sound", "s.wav"}, dir);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("at most 600 s"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "s.wav"));
    fs::remove_all(dir);
}

#ifndef VROC_TEST_NO_RENDERER   // `vroc play` is left out of builds without the renderer
TEST(CliSound, PlayWritesTheWav) {
    const fs::path dir = freshTempDir("cli-sound-play");
    const auto r = runVroc({"play", kBallDrop, "-b", "native", "--frames", "90", "--width", "32", "--height", "32",
                            "--out", "out", "--no-frames", "--sound", "out/play.wav"}, dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("sound out/play.wav: 48000 Hz"), std::string::npos) << r.out;
    const auto csv = splitLines(readText((dir / "out" / "play_events.csv").string()));
    ASSERT_GE(csv.size(), 3u);   // 1.5 s: the first two bounces (0.45 s, 0.90 s)
    EXPECT_EQ(splitCsv(csv[1]).back(), "sounded");
    const auto j = nlohmann::json::parse(readText((dir / "out" / "play.json").string()));
    EXPECT_NE(j["sound"].get<std::string>().find("impacts sounded"), std::string::npos);
    fs::remove_all(dir);
}
#endif

}  // namespace
}  // namespace vroc::test
