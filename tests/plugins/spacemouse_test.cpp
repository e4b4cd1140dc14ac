// SPDX-License-Identifier: MIT
// The simulated 3D mouse integrates scripted deflections like AnalogFly.
#include <gtest/gtest.h>

#include <cmath>

#include "plugin_test_host.h"
#include "vroc/core/errors.h"

namespace vroc::plugins::test {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int64_t kSecond = 1'000'000'000;

TEST(SpaceMouseSim, IntegratesTranslationInBaseAndRotationAboutDeviceAxes) {
    auto host = makeTestHost();
    // 1 s pushing +x with button 1; 1 s twisting about the device x axis; 1 s twisting about the
    // device z axis while pushing +y; then rest.
    auto device = host->open("spacemouse-sim",
                             "max_speed=0.5,max_rate_deg=90,x=0,y=0,z=1,"
                             "script=1:1:0:0:0:0:0:1/1:0:0:0:1:0:0/1:0:1:0:0:0:1:2");
    const Quat rx(Eigen::AngleAxisd(kPi / 2, Vec3::UnitX()));
    const Quat rz(Eigen::AngleAxisd(kPi / 2, Vec3::UnitZ()));
    struct Expect {
        int64_t t;
        Vec3 position;
        Quat orientation;
        uint64_t buttons;
    } cases[] = {
        {kSecond / 2, Vec3(0.25, 0, 1), Quat::Identity(), 1},
        {kSecond, Vec3(0.5, 0, 1), Quat::Identity(), 0},
        {2 * kSecond, Vec3(0.5, 0, 1), rx, 2},
        {3 * kSecond, Vec3(0.5, 0.5, 1), rx * rz, 0},  // body-frame turns compose on the right
        {10 * kSecond, Vec3(0.5, 0.5, 1), rx * rz, 0},
    };
    for (const Expect& e : cases) {
        const PoseResult r = device->pose(0, e.t);
        ASSERT_TRUE(r.ok());
        EXPECT_LT((r.sample.pose.position - e.position).norm(), 1e-12) << "t=" << e.t;
        EXPECT_LT(angleBetween(r.sample.pose.orientation, e.orientation), 1e-9) << "t=" << e.t;
        EXPECT_EQ(device->controls(e.t).state.buttons, e.buttons) << "t=" << e.t;
    }
    // During the last segment the body z rate, seen in the base frame, is rx * (0, 0, rate).
    const PoseResult r = device->pose(0, 2 * kSecond + kSecond / 2);
    EXPECT_LT((r.sample.angular_velocity - rx * Vec3(0, 0, kPi / 2)).norm(), 1e-9);
    EXPECT_LT((r.sample.linear_velocity - Vec3(0, 0.5, 0)).norm(), 1e-12);
    const ControlResult c = device->controls(2 * kSecond + kSecond / 2);
    ASSERT_EQ(c.state.axes.size(), 6u);
    EXPECT_EQ(c.state.axes[1], 1.0);
    EXPECT_EQ(c.state.axes[5], 1.0);
}

TEST(SpaceMouseSim, BadScriptIsInputError) {
    auto host = makeTestHost();
    EXPECT_THROW(host->open("spacemouse-sim", "script=1:2:0:0:0:0:0"), InputError);  // deflection > 1
    EXPECT_THROW(host->open("spacemouse-sim", "script=1:0:0"), InputError);
}

}  // namespace
}  // namespace vroc::plugins::test
