// SPDX-License-Identifier: MIT
// Bad input through the command line: exit code 2, exactly one line on stderr that starts with
// "vroc: error: " and names the problem, and no output directory that looks complete.
#include <signal.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include <gtest/gtest.h>

#include "csv_reader.h"
#include "subprocess.h"
#include "test_scenes.h"

namespace vroc::test {
namespace {
namespace fs = std::filesystem;

struct BadInput : ::testing::Test {
    void SetUp() override {
        dir = freshTempDir(std::string("bad-") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        scene_file = writeFile(dir / "two_bodies.json", kTwoBodyScene).string();
    }
    void TearDown() override { fs::remove_all(dir); }

    // Runs vroc and checks the contract of a bad-input failure; `needle` must appear in the line.
    void expectInputError(std::vector<std::string> args, const std::string& needle) {
        const auto r = runVroc(args, dir);
        std::string joined;
        for (const auto& a : args) joined += a + " ";
        EXPECT_EQ(r.exit_code, 2) << joined << "\n" << r.err;
        EXPECT_EQ(r.err.rfind("vroc: error: ", 0), 0u) << joined << "\n" << r.err;
        ASSERT_FALSE(r.err.empty());
        EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "not one line: " << r.err;
        EXPECT_NE(r.err.find(needle), std::string::npos) << "expected '" << needle << "' in: " << r.err;
        EXPECT_EQ(r.out, "");
        EXPECT_FALSE(fs::exists(dir / "out" / "run.json")) << joined;
        EXPECT_FALSE(fs::exists(dir / "out")) << joined << ": created an output directory for bad input";
        EXPECT_FALSE(fs::exists(dir / "runs")) << joined;
    }

    fs::path dir;
    std::string scene_file;
};

TEST_F(BadInput, MissingSceneFile) {
    expectInputError({"run", (dir / "nope.json").string(), "--backend", "bullet", "--out", "out"}, "nope.json");
}

TEST_F(BadInput, InvalidSceneFileNamesTheFile) {
    const auto bad = writeFile(dir / "broken.json", "{\"format\": \"vroc-scene/1\",\n  \"name\": ").string();
    expectInputError({"run", bad, "--backend", "bullet", "--out", "out"}, "broken.json");
}

TEST_F(BadInput, UnknownBackendListsKnownOnes) {
    expectInputError({"run", scene_file, "--backend", "havok", "--out", "out"}, "unknown backend 'havok' (known: ");
    expectInputError({"run", scene_file, "--out", "out"}, "bullet");   // missing --backend also lists them
}

TEST_F(BadInput, UnknownSetKeyListsValidKeys) {
    expectInputError({"run", scene_file, "--backend", "bullet", "--set", "bullet.substep=2", "--out", "out"},
                     "bullet.substeps");
}

TEST_F(BadInput, BadSetValueSaysWhatWasExpected) {
    expectInputError({"run", scene_file, "--backend", "bullet", "--set", "bullet.substeps=0", "--out", "out"},
                     "expected an integer");
    expectInputError({"run", scene_file, "--backend", "bullet", "--set", "bullet.ccd=maybe", "--out", "out"},
                     "true or false");
    expectInputError({"run", scene_file, "--backend", "bullet", "--set", "bullet.substeps", "--out", "out"},
                     "key=value");
}

TEST_F(BadInput, NonPositiveDtAndDuration) {
    for (const char* value : {"0", "-0.01", "nan", "inf"}) {
        expectInputError({"run", scene_file, "--backend", "bullet", "--dt", value, "--out", "out"}, "--dt");
        expectInputError({"run", scene_file, "--backend", "bullet", "--duration", value, "--out", "out"}, "--duration");
    }
    expectInputError({"run", scene_file, "--backend", "bullet", "--dt", "abc", "--out", "out"}, "--dt");
}

TEST_F(BadInput, UnwritableOutputDirectory) {
    expectInputError({"run", scene_file, "--backend", "bullet", "--out", "/proc/vroc-out"}, "/proc/vroc-out");
    writeFile(dir / "a-file", "x");
    expectInputError({"run", scene_file, "--backend", "bullet", "--out", (dir / "a-file").string()}, "not a directory");
    expectInputError({"run", scene_file, "--backend", "bullet", "--out", (dir / "a-file" / "sub").string()}, "a-file");
    EXPECT_EQ(readText((dir / "a-file").string()), "x");
}

TEST_F(BadInput, UsageErrors) {
    expectInputError({"frobnicate"}, "unknown command 'frobnicate'");
    expectInputError({}, "subcommand");
    expectInputError({"run", scene_file, "--backend", "bullet", "--no-such-option"}, "--no-such-option");
    expectInputError({"run", "--backend", "bullet"}, "scene");
}

// Failure while running: an interrupted run exits 3 and leaves no run.json (nor its directory).
TEST_F(BadInput, InterruptedRunExitsThreeWithoutRunJson) {
    const fs::path out = dir / "long";
    SpawnOptions options;
    options.stdout_file = "/dev/null";
    options.stderr_file = dir / "err";
    Subprocess run(vrocCommand({"run", scene_file, "--backend", "bullet", "--duration", "1e6", "--out", out.string()}),
                   options);
    // Signal only once the run is underway (its temporary files exist, the handler is installed).
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (!fs::exists(out / "trajectory.csv.tmp") && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    ::kill(run.pid(), SIGINT);
    // 128 + 2 would mean SIGINT ended it instead of the run stopping and exiting.
    EXPECT_EQ(run.wait(), 3);
    const std::string err = readText((dir / "err").string());
    EXPECT_EQ(err.rfind("vroc: error: interrupted", 0), 0u) << err;
    EXPECT_FALSE(fs::exists(out / "run.json"));
    EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace vroc::test
