// SPDX-License-Identifier: MIT
// The classic figure through the device plugins: the analytic plugin's head turn (peak 200 deg/s)
// measured 50 ms late, drawn as measured or through the `predict` plugin (Kalman after Azuma &
// Bishop 1994, with and without the device's velocities as "inertial" measurements).
#include <cmath>
#include <cstdio>
#include <numbers>

#include <gtest/gtest.h>

#include "vroc/hmd/registration_study.h"
#include "vroc/play/device_source.h"
#include "vroc/play/scripted_head.h"
#include "vroc/plugin/plugin_host.h"

namespace vroc::play {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

hmd::ErrorStatistics study(plugins::PluginHost& host, const std::string& drawn_spec) {
    const std::string turn = "motion=head-turn,speed_deg=200,amplitude_deg=30,x=0,y=0,z=1.6";
    PluginDevice truth(host, "analytic:" + turn);
    PluginDevice drawn(host, drawn_spec);
    hmd::HmdSettings s;
    s.ipd = 0.0;          // eye on the yaw axis: the error is the yaw difference
    s.eye_relief = 0.0;
    const hmd::StereoRig rig(s);
    const std::vector<Vec3> points = {Vec3(0.5, 2.0, 1.6), Vec3(-0.3, 3.0, 1.6)};   // eye height
    hmd::ErrorStatistics stats;
    for (int i = 0; i < 60; ++i) drawn.read(i / 60.0);   // predictors learn the motion first
    for (int i = 0; i < 240; ++i) {   // 4 s at 60 Hz, after a 1 s warm-up
        const double t = 1.0 + i / 60.0;
        stats.add(hmd::frameRegistrationError(rig, headFromSensor(truth.read(t).pose),
                                              headFromSensor(drawn.read(t).pose), points));
    }
    return stats;
}

TEST(RegistrationThroughPlugins, HeadTurnTwoHundredDegreesFiftyMilliseconds) {
    plugins::PluginHost host;
    const std::string late = "motion=head-turn,speed_deg=200,amplitude_deg=30,x=0,y=0,z=1.6,latency=0.05,rate=120";
    const hmd::ErrorStatistics none = study(host, "analytic:" + late);
    std::string inner;
    for (const char* kv : {"motion=head-turn", "speed_deg=200", "amplitude_deg=30", "x=0", "y=0", "z=1.6",
                           "latency=0.05", "rate=120"})
        inner += std::string(",inner.") + kv;
    const hmd::ErrorStatistics kalman_inertial = study(host, "predict:inner=analytic,method=kalman" + inner);
    const hmd::ErrorStatistics kalman_plain =
        study(host, "predict:inner=analytic,method=kalman,inner.velocities=0" + inner);
    const hmd::ErrorStatistics cv = study(host, "predict:inner=analytic,method=cv,inner.velocities=0" + inner);
    std::printf("peak error: none %.2f deg, cv %.3f deg, kalman %.3f deg, kalman+velocities %.3f deg\n",
                none.max() / kDeg, cv.max() / kDeg, kalman_plain.max() / kDeg, kalman_inertial.max() / kDeg);
    std::printf("rms error:  none %.2f deg, cv %.3f deg, kalman %.3f deg, kalman+velocities %.3f deg\n",
                none.rms() / kDeg, cv.rms() / kDeg, kalman_plain.rms() / kDeg, kalman_inertial.rms() / kDeg);
    // Closed form of a delayed sine yaw: peak 2 A sin(pi f L), f = speed / (2 pi A); the 120 Hz
    // tracker grid adds 0 to 8.3 ms of delay.
    const double a = 30.0, f = 200.0 / (2 * std::numbers::pi * 30.0);
    auto peak = [&](double delay) { return 2 * a * std::sin(std::numbers::pi * f * delay); };
    EXPECT_GT(none.max() / kDeg, 0.99 * peak(0.050));   // ~10 deg
    EXPECT_LT(none.max() / kDeg, peak(0.050 + 1.0 / 120.0));
    EXPECT_LT(cv.max(), 0.3 * none.max());
    EXPECT_LT(cv.rms(), 0.3 * none.rms());
    EXPECT_LT(kalman_plain.rms(), 0.3 * none.rms());
    EXPECT_LT(kalman_inertial.rms(), 0.3 * none.rms());
    // Velocity measurements help, as Azuma & Bishop found with inertial sensors.
    EXPECT_LT(kalman_inertial.rms(), kalman_plain.rms());
}

}  // namespace
}  // namespace vroc::play
