// SPDX-License-Identifier: MIT
// ABI 2's output direction through the loader: who is sent forces (ABI-2 devices declaring force
// output, never ABI-1 plugins), what is refused before it crosses the boundary, and how failures
// are counted.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "plugin_test_host.h"
#include "vroc/core/errors.h"

namespace vroc::plugins::test {
namespace {

const Vec3 kForce(1.5, -2.0, 30.0), kTorque(0.0, 0.25, -0.125);

std::string tempPath(const std::string& name) {
    return ::testing::TempDir() + "vroc-force-" + std::to_string(getpid()) + "-" + name;
}

std::vector<std::string> readLines(const std::string& path) {
    std::ifstream in(path);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

TEST(ForceOutput, AbiOnePluginLoadsWorksAndIsNeverSentForces) {
    auto host = makeTestHost();
    const LoadedPlugin& plugin = host->load(fixturePath("v1-force"));
    EXPECT_EQ(plugin.abi_version, 1u);
    EXPECT_EQ(plugin.api->struct_size, 88u);  // the ABI-1 table, as compiled against the frozen header
    ASSERT_EQ(plugin.devices.size(), 1u);
    EXPECT_TRUE(plugin.devices[0].caps & VROC_CAP_FORCE_OUTPUT);  // declared the ABI-1 way

    auto device = host->open(plugin, "");
    const PoseResult pose = device->pose(0, 2'000'000'000);
    ASSERT_TRUE(pose.ok()) << pose.message;
    EXPECT_DOUBLE_EQ(pose.sample.pose.position.x(), 0.002);  // 0.001 m/s x 2 s
    EXPECT_EQ(pose.sample.pose.position.y(), 0.2);

    EXPECT_FALSE(device->acceptsForce());
    for (int i = 0; i < 5; ++i) EXPECT_FALSE(device->sendForce(0, i, kForce, kTorque));
    EXPECT_EQ(device->sentForces(), 0u);
    EXPECT_EQ(device->rejectedForces(), 0u);  // not accepting forces is not a failure
    // Neither the ABI-1 set_force was called nor a "send_force" read past the 88-byte table.
    const ControlResult calls = device->controls(0);
    ASSERT_TRUE(calls.ok());
    EXPECT_EQ(calls.state.buttons & 0xffffffffu, 0u) << "set_force calls";
    EXPECT_EQ(calls.state.buttons >> 32, 0u) << "calls through the word past the table";
}

TEST(ForceOutput, DevicesWithoutForceOutputTakeNone) {
    auto host = makeTestHost();
    auto device = host->open("analytic", "motion=static");
    EXPECT_EQ(device->plugin().abi_version, 2u);
    EXPECT_FALSE(device->acceptsForce());
    EXPECT_FALSE(device->sendForce(0, 0, kForce, kTorque));
    EXPECT_EQ(device->rejectedForces(), 0u);
}

TEST(ForceOutput, AbiTwoDeviceTakesForcesAndTheHostRefusesBadOnesBeforeTheBoundary) {
    auto capture = std::make_shared<LogCapture>();
    auto host = makeTestHost(capture);
    const std::string out = tempPath("refuse.csv");
    {
        auto device = host->open("force-log", "out=" + out + ",inner=analytic,inner.motion=static");
        EXPECT_EQ(device->plugin().abi_version, 2u);
        ASSERT_TRUE(device->acceptsForce());
        EXPECT_TRUE(device->sendForce(0, 10, kForce, kTorque));
        const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
        EXPECT_FALSE(device->sendForce(0, 11, Vec3(0, nan, 0), kTorque));
        EXPECT_FALSE(device->sendForce(0, 12, kForce, Vec3(0, 0, -inf)));
        EXPECT_FALSE(device->sendForce(16, 13, kForce, kTorque));  // force-log declares sensors 0..15
        EXPECT_TRUE(device->sendForce(15, 14, kForce, kTorque));
        EXPECT_EQ(device->sentForces(), 2u);
        EXPECT_EQ(device->rejectedForces(), 3u);
    }
    // Logged once with the reason of the first refusal; the refused ones never reached the plugin.
    EXPECT_EQ(capture->count("force not sent: force is not finite (component 1 = nan)"), 1u);
    EXPECT_EQ(capture->count("force not sent"), 1u);
    const auto lines = readLines(out);
    ASSERT_EQ(lines.size(), 3u);
    EXPECT_EQ(lines[1].rfind("10,0,", 0), 0u);
    EXPECT_EQ(lines[2].rfind("14,15,", 0), 0u);
    std::filesystem::remove(out);
}

TEST(ForceOutput, PluginFailureIsCountedAndItsReasonLoggedOnce) {
    auto capture = std::make_shared<LogCapture>();
    auto host = makeTestHost(capture);
    auto device = host->open(fixturePath("force-fails"));
    ASSERT_TRUE(device->acceptsForce());
    for (int i = 0; i < 3; ++i) EXPECT_FALSE(device->sendForce(0, i, kForce, kTorque));
    EXPECT_EQ(device->rejectedForces(), 3u);
    EXPECT_EQ(device->sentForces(), 0u);
    EXPECT_EQ(capture->count("force not sent: send_force failed (-5): force-fails: motor amplifier not powered"), 1u);
}

TEST(ForceOutput, AnAbiOneHostNegotiatesVersionOneAndSeesNoForceOutput) {
    HostOptions options;
    options.search_dirs = {VROC_TEST_PLUGIN_DIR};
    options.use_environment = false;
    options.use_default_dirs = false;
    options.log = [](int32_t, const std::string&, const std::string&) {};
    options.abi_max = 1;
    PluginHost old_host(options);
    const LoadedPlugin& plugin = old_host.load("force-log");
    EXPECT_EQ(plugin.abi_version, 1u);
    // ABI 1 has no send_force and the SDK leaves set_force NULL, so the device must not claim force
    // output (an ABI-1 host would otherwise reject it for a null set_force).
    EXPECT_FALSE(plugin.capabilities & VROC_CAP_FORCE_OUTPUT);
    const std::string out = tempPath("old-host.csv");
    {
        auto device = old_host.open(plugin, "out=" + out + ",inner=analytic");
        EXPECT_FALSE(device->acceptsForce());
        EXPECT_FALSE(device->sendForce(0, 0, kForce, kTorque));
    }
    EXPECT_EQ(readLines(out).size(), 1u);  // the header alone
    std::filesystem::remove(out);
}

// An ABI-1 plugin declaring force output must still have the ABI-1 set_force (the ABI-1 rule is
// kept), linked in and checked like a loaded one.
int32_t abiOneForceWithoutSetForce(const VrocHostInfo*, VrocPluginInfo* out) {
    static const VrocDeviceApi api = {
        VROC_STRUCT_DEVICE_API, 1, VROC_DEVICE_API_SIZE_V1,
        [](uint32_t, VrocDeviceDesc* d) -> int32_t {
            d->kind = VROC_DEVICE_HAND_TRACKER;
            d->sensor_count = 1;
            d->caps = VROC_CAP_POSE_SOURCE | VROC_CAP_FORCE_OUTPUT;
            return VROC_OK;
        },
        [](uint32_t, const char*, VrocDeviceHandle*) -> int32_t { return VROC_ERROR_GENERIC; },
        [](VrocDeviceHandle) -> int32_t { return VROC_OK; }, [](VrocDeviceHandle) -> int32_t { return VROC_OK; },
        [](VrocDeviceHandle) {},
        [](VrocDeviceHandle, uint32_t, int64_t, VrocPoseSample*) -> int32_t { return VROC_ERROR_NO_DATA; },
        [](VrocDeviceHandle, int64_t, VrocControlState*) -> int32_t { return VROC_ERROR_UNSUPPORTED; },
        [](VrocDeviceHandle, char* b, uint64_t n) -> int32_t {
            if (n) b[0] = '\0';
            return 0;
        },
        nullptr, nullptr};
    out->abi_version = 1;
    out->device_count = 1;
    out->name = "abi1-no-set-force";
    out->version = "1";
    out->api = &api;
    return VROC_OK;
}

TEST(ForceOutput, AbiOneForceOutputWithoutSetForceIsRejected) {
    auto host = makeTestHost();
    try {
        host->addStatic("abi1", &abiOneForceWithoutSetForce);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "plugin static:abi1: device 0: force output declared but set_force is null (ABI 1)");
    }
}

}  // namespace
}  // namespace vroc::plugins::test
