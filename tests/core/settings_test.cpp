// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include "vroc/core/backend_registry.h"
#include "vroc/core/errors.h"
#include "vroc/core/settings.h"
#include "vroc/core/state_hash.h"

namespace vroc {
namespace {

std::vector<SettingSpec> sampleSpecs() {
    SettingSpec substeps{"x.substeps", SettingSpec::Type::Integer, "4", 1, 1000, {}, "internal steps per frame"};
    SettingSpec mode{"x.mode", SettingSpec::Type::Choice, "fast", 0, 0, {"fast", "exact"}, "solver mode"};
    SettingSpec ccd{"x.ccd", SettingSpec::Type::Boolean, "false", 0, 0, {}, "continuous collision"};
    SettingSpec margin{"x.margin", SettingSpec::Type::Real, "0.01", 0, 1, {}, "margin [m]"};
    return {substeps, mode, ccd, margin};
}

TEST(Settings, DefaultsAndOverrides) {
    Settings s = resolveSettings(sampleSpecs(), {{"x.substeps", "8"}, {"x.ccd", "true"}});
    EXPECT_EQ(s.integer("x.substeps"), 8);
    EXPECT_TRUE(s.boolean("x.ccd"));
    EXPECT_EQ(s.text("x.mode"), "fast");
    EXPECT_DOUBLE_EQ(s.real("x.margin"), 0.01);
}

TEST(Settings, UnknownKeyListsValidKeys) {
    try {
        resolveSettings(sampleSpecs(), {{"x.substep", "8"}});
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        std::string msg = e.what();
        EXPECT_NE(msg.find("unknown key 'x.substep'"), std::string::npos) << msg;
        EXPECT_NE(msg.find("x.substeps"), std::string::npos) << msg;
        EXPECT_NE(msg.find("x.mode"), std::string::npos) << msg;
    }
}

TEST(Settings, BadValuesAreRejected) {
    EXPECT_THROW(resolveSettings(sampleSpecs(), {{"x.substeps", "0"}}), InputError);
    EXPECT_THROW(resolveSettings(sampleSpecs(), {{"x.substeps", "2.5"}}), InputError);
    EXPECT_THROW(resolveSettings(sampleSpecs(), {{"x.mode", "slow"}}), InputError);
    EXPECT_THROW(resolveSettings(sampleSpecs(), {{"x.ccd", "maybe"}}), InputError);
    EXPECT_THROW(resolveSettings(sampleSpecs(), {{"x.margin", "nan"}}), InputError);
    EXPECT_THROW(resolveSettings(sampleSpecs(), {{"x.margin", "2"}}), InputError);
    EXPECT_THROW(splitAssignment("novalue"), InputError);
    EXPECT_EQ(splitAssignment("a=b=c").second, "b=c");
}

TEST(StateHash, DependsOnEveryBit) {
    std::vector<BodyState> states(2);
    states[1].pose.position = Vec3(1, 2, 3);
    const std::uint64_t h0 = stateHash(states);
    EXPECT_EQ(h0, stateHash(states));
    states[1].angular_velocity.z() = std::nextafter(0.0, 1.0);
    EXPECT_NE(h0, stateHash(states));
    states[1].angular_velocity.z() = -0.0;
    EXPECT_NE(h0, stateHash(states));
    EXPECT_EQ(hashToHex(0x1234).size(), 16u);
}

TEST(BackendRegistry, UnknownNameListsKnown) {
    BackendRegistry registry;
    BackendInfo info;
    info.name = "alpha";
    info.create = [](const Scene&, const Settings&) -> std::unique_ptr<Backend> { return nullptr; };
    registry.add(info);
    EXPECT_THROW(registry.add(info), std::logic_error);
    try {
        registry.require("beta");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("known: alpha"), std::string::npos);
    }
}

}  // namespace
}  // namespace vroc
