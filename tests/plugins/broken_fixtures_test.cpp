// SPDX-License-Identifier: MIT
// Every deliberately broken plugin is rejected with one clear line, and the host survives.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>

#include "plugin_test_host.h"
#include "vroc/core/errors.h"

namespace vroc::plugins::test {
namespace {

struct LoadCase {
    const char* fixture;
    const char* message;
};

class BrokenPluginLoad : public ::testing::TestWithParam<LoadCase> {};

TEST_P(BrokenPluginLoad, RejectedWithOneClearLine) {
    auto host = makeTestHost();
    const std::string path = fixturePath(GetParam().fixture);
    try {
        host->load(path);
        FAIL() << "accepted " << path;
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind("plugin " + path + ": ", 0), 0u) << what;
        EXPECT_NE(what.find(GetParam().message), std::string::npos) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
    // The host still works after the rejection.
    EXPECT_EQ(host->load("analytic").name, "analytic");
}

INSTANTIATE_TEST_SUITE_P(
    Fixtures, BrokenPluginLoad,
    ::testing::Values(LoadCase{"no-entry", "no exported symbol vroc_plugin_negotiate (not a VROC device plugin)"},
                      LoadCase{"wrong-abi", "ABI version 99 not supported (host accepts 1..2)"},
                      LoadCase{"small-struct",
                               "function table is too small for ABI 2 (struct_size 56 bytes, host needs at least 96)"},
                      LoadCase{"v2-short-table",
                               "function table is too small for ABI 2 (struct_size 88 bytes, host needs at least 96)"},
                      LoadCase{"force-no-send", "device 0: force output declared but send_force is null"},
                      LoadCase{"null-table", "null function table"},
                      LoadCase{"negotiate-fails", "vroc_plugin_negotiate failed with code -1"}),
    [](const auto& info) {
        std::string name = info.param.fixture;
        for (char& c : name)
            if (c == '-') c = '_';
        return name;
    });

TEST(BrokenPlugin, NotALibraryOrMissingFile) {
    auto host = makeTestHost();
    const std::string text_file = ::testing::TempDir() + "vroc-plugin-text-" + std::to_string(getpid()) + ".so";
    std::FILE* f = std::fopen(text_file.c_str(), "w");
    ASSERT_NE(f, nullptr);
    std::fputs("not an ELF file\n", f);
    std::fclose(f);
    for (const std::string& path : {text_file, std::string("/nonexistent/vroc-plugin-x.so")}) {
        try {
            host->load(path);
            FAIL() << path;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("plugin " + path + ": cannot load: "), std::string::npos) << e.what();
        }
    }
}

TEST(BrokenPlugin, FailingOpenReportsLastError) {
    auto host = makeTestHost();
    const LoadedPlugin& plugin = host->load(fixturePath("open-fails"));  // negotiation itself is fine
    try {
        host->open(plugin, "");
        FAIL() << "opened";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("cannot open device 0: open-fails: cannot open /dev/vroc-nothing: no such device"),
                  std::string::npos) << what;
    }
}

TEST(BrokenPlugin, NonFinitePosesAreRejectedCountedAndLoggedOnce) {
    auto capture = std::make_shared<LogCapture>();
    auto host = makeTestHost(capture);
    auto device = host->open(fixturePath("nan-pose"));
    for (int i = 1; i <= 3; ++i) {
        const PoseResult result = device->pose(0, 1000 * i);
        EXPECT_EQ(result.status, SampleStatus::Rejected);
        EXPECT_NE(result.message.find("position is not finite (component 1 = nan)"), std::string::npos) << result.message;
        EXPECT_EQ(device->rejectedSamples(), static_cast<uint64_t>(i));
    }
    EXPECT_EQ(capture->count("sample rejected: position is not finite"), 1u);
}

}  // namespace
}  // namespace vroc::plugins::test
