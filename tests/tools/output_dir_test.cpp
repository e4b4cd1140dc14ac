// SPDX-License-Identifier: MIT
// Default output directories: <parent>/<portable words>-<UTC stamp>, never one that exists.
#include <gtest/gtest.h>

#include <ctime>
#include <regex>

#include "test_scenes.h"
#include "vroc/core/recording/output_dir.h"

namespace vroc::test {
namespace {
namespace fs = std::filesystem;

TEST(TimestampedOutputDir, PortableWordsAndTheUtcTimeOfNow) {
    const fs::path parent = freshTempDir("output-dir");
    const std::time_t before = std::time(nullptr);
    const fs::path dir = recording::timestampedOutputDir({"compare", "stair case/1", ""}, parent);
    const std::time_t after = std::time(nullptr);
    EXPECT_EQ(dir.parent_path(), parent);
    std::smatch m;
    const std::string name = dir.filename().string();
    ASSERT_TRUE(std::regex_match(name, m, std::regex(R"(compare-stair_case_1-unnamed-(\d{4})(\d\d)(\d\d)-(\d\d)(\d\d)(\d\d))")))
        << name;
    std::tm utc{};
    utc.tm_year = std::stoi(m[1]) - 1900;
    utc.tm_mon = std::stoi(m[2]) - 1;
    utc.tm_mday = std::stoi(m[3]);
    utc.tm_hour = std::stoi(m[4]);
    utc.tm_min = std::stoi(m[5]);
    utc.tm_sec = std::stoi(m[6]);
    const std::time_t stamp = timegm(&utc);
    EXPECT_GE(stamp, before);
    EXPECT_LE(stamp, after);
    EXPECT_FALSE(fs::exists(dir)) << "not created";
}

TEST(TimestampedOutputDir, ATakenNameGetsANumber) {
    const fs::path parent = freshTempDir("output-dir-taken");
    // Within one second the stamp repeats; a second that turned over gives a fresh name instead.
    for (int attempt = 0; attempt < 3; ++attempt) {
        const fs::path first = recording::timestampedOutputDir({"run"}, parent);
        fs::create_directories(first);
        const fs::path second = recording::timestampedOutputDir({"run"}, parent);
        fs::create_directories(second);
        const fs::path third = recording::timestampedOutputDir({"run"}, parent);
        if (second.string().rfind(first.string(), 0) != 0 || third.string().rfind(first.string(), 0) != 0) continue;
        EXPECT_EQ(second.string(), first.string() + "-2");
        EXPECT_EQ(third.string(), first.string() + "-3");
        return;
    }
    FAIL() << "the clock turned over a second three times in a row";
}

}  // namespace
}  // namespace vroc::test
