// SPDX-License-Identifier: MIT
// ABI negotiation, search rules and the static registration path.
#include <dlfcn.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "plugin_test_host.h"
#include "vroc/core/errors.h"

extern "C" void vroc_abi_sizes_from_c(uint64_t out[8]);

namespace vroc::plugins::test {
namespace {

TEST(PluginAbi, CAndCppAgreeOnStructSizes) {
    uint64_t c_sizes[8];
    vroc_abi_sizes_from_c(c_sizes);
    const uint64_t cpp_sizes[8] = {sizeof(VrocHostServices), sizeof(VrocHostInfo),   sizeof(VrocPluginInfo),
                                   sizeof(VrocDeviceApi),    sizeof(VrocDeviceDesc), sizeof(VrocPoseSample),
                                   sizeof(VrocControlState), sizeof(VrocForceCommand)};
    for (int i = 0; i < 8; ++i) EXPECT_EQ(c_sizes[i], cpp_sizes[i]) << "struct #" << i;
}

TEST(PluginNegotiation, AnalyticDeclaresItself) {
    auto host = makeTestHost();
    const LoadedPlugin& plugin = host->load("analytic");
    EXPECT_EQ(plugin.name, "analytic");
    EXPECT_EQ(plugin.version, "1.1.0");
    EXPECT_EQ(plugin.abi_version, VROC_PLUGIN_ABI_VERSION);
    EXPECT_EQ(plugin.path, std::string(VROC_TEST_PLUGIN_DIR) + "/vroc-plugin-analytic.so");
    ASSERT_EQ(plugin.devices.size(), 1u);
    EXPECT_EQ(plugin.devices[0].sensor_count, 1u);
    EXPECT_TRUE(plugin.capabilities & VROC_CAP_POSE_SOURCE);
    EXPECT_TRUE(plugin.capabilities & VROC_CAP_BUTTONS);
    EXPECT_FALSE(plugin.capabilities & VROC_CAP_FORCE_OUTPUT);
    EXPECT_EQ(capabilityNames(VROC_CAP_POSE_SOURCE | VROC_CAP_ANALOG_AXES), "pose-source,analog-axes");
    // Loading again returns the same validated plugin.
    EXPECT_EQ(&host->load("analytic"), &plugin);
}

TEST(PluginNegotiation, EveryBuiltinLoadsAndExportsOnlyTheEntryPoint) {
    auto host = makeTestHost();
    for (const char* name : {"analytic", "replay", "spacemouse-sim", "udp", "predict", "force-log", "spacenav"}) {
        const LoadedPlugin& plugin = host->load(name);
        EXPECT_EQ(plugin.name, name);
        EXPECT_FALSE(plugin.devices.empty());
        // A hidden symbol of the SDK must not be reachable.
        void* library = dlopen(plugin.path.c_str(), RTLD_NOW | RTLD_LOCAL | RTLD_NOLOAD);
        ASSERT_NE(library, nullptr);
        EXPECT_NE(dlsym(library, "vroc_plugin_negotiate"), nullptr);
        EXPECT_EQ(dlsym(library, "_ZN4vroc10plugin_sdk9negotiateERKNS0_16PluginDefinitionEPK12VrocHostInfoP14VrocPluginInfo"),
                  nullptr) << name;
        dlclose(library);
    }
}

// Calls the plugin's entry point directly with hand-made host structs.
struct RawNegotiation {
    void* library;
    VrocNegotiateFn negotiate;
    explicit RawNegotiation(const std::string& path) {
        library = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        negotiate = library ? reinterpret_cast<VrocNegotiateFn>(dlsym(library, "vroc_plugin_negotiate")) : nullptr;
    }
    ~RawNegotiation() {
        if (library) dlclose(library);
    }
};

TEST(PluginNegotiation, PluginRefusesHostRangeWithoutItsVersionAndTooSmallOutput) {
    RawNegotiation raw(std::string(VROC_TEST_PLUGIN_DIR) + "/vroc-plugin-analytic.so");
    ASSERT_NE(raw.negotiate, nullptr);
    VrocHostInfo host{VROC_STRUCT_HOST_INFO, 1, sizeof(VrocHostInfo), 3, 4, "future host", nullptr};
    VrocPluginInfo info{};
    info.struct_type = VROC_STRUCT_PLUGIN_INFO;
    info.struct_version = 1;
    info.struct_size = sizeof info;
    EXPECT_EQ(raw.negotiate(&host, &info), VROC_ERROR_ABI);
    EXPECT_EQ(info.api, nullptr);  // nothing written on refusal

    host.abi_min = host.abi_max = 1;
    info.struct_size = offsetof(VrocPluginInfo, api);  // a host that knows fewer fields
    EXPECT_EQ(raw.negotiate(&host, &info), VROC_ERROR_ABI);
    EXPECT_EQ(info.api, nullptr);

    info.struct_size = sizeof info;
    EXPECT_EQ(raw.negotiate(&host, &info), VROC_OK);  // works without services too
    EXPECT_EQ(info.abi_version, 1u);
    EXPECT_NE(info.api, nullptr);
}

// The SDK answers with the highest version both sides know.
TEST(PluginNegotiation, SdkPluginChoosesTheHighestCommonVersion) {
    RawNegotiation raw(std::string(VROC_TEST_PLUGIN_DIR) + "/vroc-plugin-analytic.so");
    ASSERT_NE(raw.negotiate, nullptr);
    const struct {
        uint32_t min, max;
        int32_t rc;
        uint32_t chosen;
    } cases[] = {{1, 1, VROC_OK, 1}, {1, 2, VROC_OK, 2}, {2, 2, VROC_OK, 2}, {1, 9, VROC_OK, 2},
                 {2, 9, VROC_OK, 2}, {3, 9, VROC_ERROR_ABI, 0}};
    for (const auto& c : cases) {
        VrocHostInfo host{VROC_STRUCT_HOST_INFO, 1, sizeof(VrocHostInfo), c.min, c.max, "host", nullptr};
        VrocPluginInfo info{};
        info.struct_type = VROC_STRUCT_PLUGIN_INFO;
        info.struct_version = 1;
        info.struct_size = sizeof info;
        EXPECT_EQ(raw.negotiate(&host, &info), c.rc) << c.min << ".." << c.max;
        EXPECT_EQ(info.abi_version, c.chosen) << c.min << ".." << c.max;
        if (c.rc == VROC_OK) {
            // The same table serves both versions: large enough for ABI 2, ABI-1 set_force unused.
            EXPECT_GE(info.api->struct_size, VROC_DEVICE_API_SIZE_V2);
            EXPECT_EQ(info.api->set_force, nullptr);
            EXPECT_NE(info.api->send_force, nullptr);
        }
    }
}

TEST(PluginNegotiation, HostOffersOneToTwoAndCanActAsAnAbiOneHost) {
    auto host = makeTestHost();
    EXPECT_EQ(host->load("analytic").abi_version, 2u);
    HostOptions options;
    options.search_dirs = {VROC_TEST_PLUGIN_DIR};
    options.use_environment = false;
    options.use_default_dirs = false;
    options.log = [](int32_t, const std::string&, const std::string&) {};
    options.abi_max = 1;
    PluginHost old_host(options);
    EXPECT_EQ(old_host.load("analytic").abi_version, 1u);
    options.abi_max = 3;
    EXPECT_THROW(PluginHost{options}, InputError);
}

// A plugin linked into the program: the same validation without dlopen.
int32_t staticNegotiate(const VrocHostInfo* host, VrocPluginInfo* out) {
    static const VrocDeviceApi api = {
        VROC_STRUCT_DEVICE_API, 1, sizeof(VrocDeviceApi),
        [](uint32_t, VrocDeviceDesc* d) -> int32_t {
            d->kind = VROC_DEVICE_BUTTONS;
            d->button_count = 3;
            d->caps = VROC_CAP_BUTTONS;
            d->name = "three buttons";
            return VROC_OK;
        },
        [](uint32_t, const char*, VrocDeviceHandle* h) -> int32_t {
            static int device;
            *h = reinterpret_cast<VrocDeviceHandle>(&device);
            return VROC_OK;
        },
        [](VrocDeviceHandle) -> int32_t { return VROC_OK; }, [](VrocDeviceHandle) -> int32_t { return VROC_OK; },
        [](VrocDeviceHandle) {},
        [](VrocDeviceHandle, uint32_t, int64_t, VrocPoseSample*) -> int32_t { return VROC_ERROR_UNSUPPORTED; },
        [](VrocDeviceHandle, int64_t t, VrocControlState* c) -> int32_t {
            c->time_ns = t;
            c->buttons = 0b101;
            return VROC_OK;
        },
        [](VrocDeviceHandle, char* b, uint64_t n) -> int32_t {
            if (n) b[0] = '\0';
            return 0;
        },
        nullptr, nullptr};
    if (host->abi_min > 1 || host->abi_max < 1) return VROC_ERROR_ABI;
    out->abi_version = 1;
    out->device_count = 1;
    out->name = "static-buttons";
    out->version = "2.0";
    out->api = &api;
    return VROC_OK;
}

TEST(PluginNegotiation, StaticRegistrationUsesTheSameChecks) {
    auto host = makeTestHost();
    const LoadedPlugin& plugin = host->addStatic("buttons", &staticNegotiate);
    EXPECT_EQ(plugin.path, "static:buttons");
    EXPECT_EQ(plugin.capabilities, VROC_CAP_BUTTONS);
    auto device = host->open(plugin, "");
    const ControlResult controls = device->controls(42);
    ASSERT_TRUE(controls.ok());
    EXPECT_EQ(controls.state.buttons, 0b101u);
    EXPECT_EQ(controls.state.time_ns, 42);
    EXPECT_EQ(device->pose(0, 0).status, SampleStatus::Failed);
}

// The same table with one required entry missing: rejected by name of the entry.
int32_t staticNegotiateWithoutGetPose(const VrocHostInfo* host, VrocPluginInfo* out) {
    static VrocDeviceApi api;
    const int32_t rc = staticNegotiate(host, out);
    api = *out->api;
    api.get_pose = nullptr;
    out->api = &api;
    return rc;
}

TEST(PluginNegotiation, NullEntryInTableIsRejectedByName) {
    auto host = makeTestHost();
    try {
        host->addStatic("no-get-pose", &staticNegotiateWithoutGetPose);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "plugin static:no-get-pose: function table entry 'get_pose' is null");
    }
}

TEST(PluginSearch, ByNameByPathAndByEnvironment) {
    auto host = makeTestHost();
    const std::string path = std::string(VROC_TEST_PLUGIN_DIR) + "/vroc-plugin-replay.so";
    EXPECT_EQ(host->resolve("replay"), path);
    EXPECT_EQ(host->resolve(path), path);
    try {
        host->resolve("no-such-device");
        FAIL() << "resolved a missing plugin";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("vroc-plugin-no-such-device.so not found in " VROC_TEST_PLUGIN_DIR),
                  std::string::npos) << e.what();
    }
    // VROC_PLUGIN_PATH: the fixture directory is not searched unless named there.
    HostOptions options;
    options.use_default_dirs = false;
    options.log = [](int32_t, const std::string&, const std::string&) {};
    setenv(kPluginPathVariable, "/nonexistent:" VROC_TEST_FIXTURE_DIR, 1);
    PluginHost env_host(options);
    unsetenv(kPluginPathVariable);
    EXPECT_EQ(env_host.searchDirs().size(), 2u);
    EXPECT_EQ(env_host.resolve("fixture-nan-pose"), fixturePath("nan-pose"));
    EXPECT_EQ(env_host.load("fixture-nan-pose").name, "nan-pose");
    // findPluginFiles lists only vroc-plugin-*.so, sorted.
    const auto files = findPluginFiles({VROC_TEST_PLUGIN_DIR});
    ASSERT_EQ(files.size(), 7u);
    EXPECT_EQ(files.front(), std::string(VROC_TEST_PLUGIN_DIR) + "/vroc-plugin-analytic.so");
}

TEST(PluginOptions, UnknownOrBadOptionIsOneLineInputError) {
    auto host = makeTestHost();
    const std::pair<const char*, const char*> cases[] = {
        {"motion=circle,bogus=1", "analytic: unknown option 'bogus'"},
        {"motion=zigzag", "analytic: option motion='zigzag': expected static, circle"},
        {"radius=abc", "analytic: option radius='abc': expected a finite number"},
        {"radius", "analytic: option 'radius' is not key=value"},
    };
    for (const auto& [options, expected] : cases) {
        try {
            host->open("analytic", options);
            FAIL() << options;
        } catch (const InputError& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find(expected), std::string::npos) << what;
            EXPECT_EQ(what.find('\n'), std::string::npos);
        }
    }
    EXPECT_EQ(parseDeviceSpec("analytic:motion=spin,rate=90").options, "motion=spin,rate=90");
    EXPECT_EQ(parseDeviceSpec("udp").plugin, "udp");
}

}  // namespace
}  // namespace vroc::plugins::test
