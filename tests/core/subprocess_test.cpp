// SPDX-License-Identifier: MIT
// Subprocess: argument vectors reach the program word for word (no shell), exit statuses and
// signals come back as a shell reports them, stdin is a pipe or /dev/null, output goes to files.
#include <gtest/gtest.h>

#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "vroc/core/errors.h"
#include "vroc/core/subprocess.h"

namespace vroc {
namespace {
namespace fs = std::filesystem;

fs::path tempDir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("vroc-subprocess-test-" + std::to_string(::getpid()) + "-" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string slurp(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST(Subprocess, ArgumentsArriveWordForWord) {
    const fs::path dir = tempDir("words");
    SpawnOptions o;
    o.stdout_file = dir / "out";
    // Words a shell would split, expand or read as syntax.
    const std::vector<std::string> words = {"a b", "it's", "$HOME", "*", "\"q\"", "x;y|z", ""};
    std::vector<std::string> argv = {"printf", "[%s]"};
    argv.insert(argv.end(), words.begin(), words.end());
    EXPECT_EQ(runProcess(argv, o), 0);
    EXPECT_EQ(slurp(dir / "out"), "[a b][it's][$HOME][*][\"q\"][x;y|z][]");
}

TEST(Subprocess, ExitCodesAndSignalsAreReportedAsAShellDoes) {
    EXPECT_EQ(runProcess({"sh", "-c", "exit 0"}), 0);
    EXPECT_EQ(runProcess({"sh", "-c", "exit 3"}), 3);
    EXPECT_EQ(runProcess({"sh", "-c", "kill -TERM $$"}), 128 + SIGTERM);
}

TEST(Subprocess, AMissingProgramIsARunErrorNamingIt) {
    try {
        runProcess({"vroc-no-such-program-xyz"});
        FAIL() << "expected RunError";
    } catch (const RunError& e) {
        EXPECT_NE(std::string(e.what()).find("vroc-no-such-program-xyz"), std::string::npos) << e.what();
    }
    SpawnOptions o;
    o.stderr_file = "/proc/no-such-dir/log";
    EXPECT_THROW(runProcess({"true"}, o), RunError);
}

TEST(Subprocess, StdinPipeCarriesBinaryDataAndStderrCanShareTheLogFile) {
    const fs::path dir = tempDir("pipe");
    SpawnOptions o;
    o.stdin_pipe = true;
    o.stdout_file = o.stderr_file = dir / "log";
    std::string data(300000, '\0');   // more than a pipe buffer holds
    for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<char>(i * 7 + 3);
    Subprocess p({"sh", "-c", "cat; echo done >&2"}, o);
    ASSERT_TRUE(p.write(data.data(), data.size()));
    EXPECT_EQ(p.wait(), 0);
    EXPECT_EQ(slurp(dir / "log"), data + "done\n");
}

TEST(Subprocess, WithoutAPipeStdinIsEmptyAndTheWorkingDirectoryIsSet) {
    const fs::path dir = tempDir("cwd");
    SpawnOptions o;
    o.stdout_file = dir / "out";
    o.working_directory = dir;
    EXPECT_EQ(runProcess({"sh", "-c", "wc -c; pwd"}, o), 0);
    EXPECT_EQ(slurp(dir / "out"), "0\n" + fs::canonical(dir).string() + "\n");
}

TEST(Subprocess, WritingToAChildThatExitedFailsWithoutSigpipe) {
    SpawnOptions o;
    o.stdin_pipe = true;
    Subprocess p({"true"}, o);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (!p.poll() && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    ASSERT_EQ(p.poll(), 0);
    const std::string data(1 << 16, 'x');
    EXPECT_FALSE(p.write(data.data(), data.size()));   // SIGPIPE would have ended the test program
    sigset_t pending;
    sigpending(&pending);
    EXPECT_EQ(sigismember(&pending, SIGPIPE), 0) << "a SIGPIPE was left pending";
    EXPECT_EQ(p.wait(), 0);
}

}  // namespace
}  // namespace vroc
