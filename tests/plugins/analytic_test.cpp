// SPDX-License-Identifier: MIT
// The analytic plugin against its closed forms, recomputed here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "plugin_test_host.h"
#include "vroc/core/errors.h"

namespace vroc::plugins::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(AnalyticPlugin, CirclePoseAndVelocityMatchClosedForm) {
    auto host = makeTestHost();
    auto device = host->open("analytic", "motion=circle,radius=0.5,period=4,x=1,y=2,z=3");
    for (double t : {0.0, 0.37, 1.0, 2.5, 3.99}) {
        const int64_t ns = static_cast<int64_t>(std::llround(t * 1e9));
        const PoseResult r = device->pose(0, ns);
        ASSERT_TRUE(r.ok()) << r.message;
        const double a = 2 * kPi / 4 * (ns * 1e-9);
        const Vec3 expected(1 + 0.5 * std::cos(a), 2 + 0.5 * std::sin(a), 3);
        EXPECT_LT((r.sample.pose.position - expected).norm(), 1e-12) << "t=" << t;
        const Quat q(Eigen::AngleAxisd(a + kPi / 2, Vec3::UnitZ()));
        EXPECT_LT(angleBetween(r.sample.pose.orientation, q), 1e-12) << "t=" << t;
        EXPECT_EQ(r.sample.time_ns, ns);
        // Velocity against a central difference of the reported positions.
        const int64_t h = 1000;  // 1 us
        const Vec3 diff = (device->pose(0, ns + h).sample.pose.position - device->pose(0, ns - h).sample.pose.position) / 2e-6;
        EXPECT_LT((r.sample.linear_velocity - diff).norm(), 1e-6) << "t=" << t;
        EXPECT_NEAR(r.sample.angular_velocity.z(), 2 * kPi / 4, 1e-12);
    }
}

TEST(AnalyticPlugin, LatencyAndRateGiveDelayedGridMeasurements) {
    auto host = makeTestHost();
    auto device = host->open("analytic", "motion=spin,speed_deg=90,latency=0.05,rate=100");
    const int64_t asked = 1'234'567'891;
    const PoseResult r = device->pose(0, asked);
    ASSERT_TRUE(r.ok());
    const int64_t measured = (asked - 50'000'000) / 10'000'000 * 10'000'000;  // 1.18 s
    EXPECT_EQ(r.sample.time_ns, measured);
    EXPECT_EQ(r.sample.sequence, 118u);
    const Quat q(Eigen::AngleAxisd(kPi / 2 * measured * 1e-9, Vec3::UnitZ()));
    EXPECT_LT(angleBetween(r.sample.pose.orientation, q), 1e-12);
}

TEST(AnalyticPlugin, ThrowHoldsButtonUntilReleaseAtTheRequestedSpeed) {
    auto host = makeTestHost();
    auto device = host->open("analytic", "motion=throw,radius=0.6,throw_speed=3,period=2");
    // Release after sweeping from -pi/2 to 0.5 rad under constant acceleration from rest.
    const double release = 2 * (0.5 + kPi / 2) * 0.6 / 3.0;
    const int64_t before = static_cast<int64_t>((release - 1e-6) * 1e9), after = static_cast<int64_t>((release + 1e-6) * 1e9);
    EXPECT_EQ(device->controls(before).state.buttons, 1u);
    EXPECT_EQ(device->controls(after).state.buttons, 0u);
    const PoseResult r = device->pose(0, before);
    ASSERT_TRUE(r.ok());
    EXPECT_NEAR(r.sample.linear_velocity.norm(), 3.0, 1e-4);
    // Moving forward (+x) and up at 0.5 rad above the horizontal.
    EXPECT_NEAR(std::atan2(r.sample.linear_velocity.z(), r.sample.linear_velocity.x()), 0.5, 1e-5);
    EXPECT_LT((r.sample.pose.position - Vec3(0.6 * std::sin(0.5), 0, 1.2 - 0.6 * std::cos(0.5))).norm(), 1e-5);
}

TEST(AnalyticPlugin, LineMovesAtConstantVelocityWithFixedOrientationAndButtonHeld) {
    auto host = makeTestHost();
    // A 30 deg yaw as [x, y, z, w]; moving (0.3, -0.1, 0.05) m/s from (1, 2, 0.5) for 2 s, button
    // from 0.25 s.
    const double h = kPi / 12;
    char quat[96];
    std::snprintf(quat, sizeof quat, "qx=0,qy=0,qz=%.17g,qw=%.17g", std::sin(h), std::cos(h));
    auto device = host->open("analytic", std::string("motion=line,x=1,y=2,z=0.5,vx=0.3,vy=-0.1,vz=0.05,") + quat +
                                             ",press_at=0.25,duration=2");
    const Vec3 start(1, 2, 0.5), v(0.3, -0.1, 0.05);
    const Quat q(Eigen::AngleAxisd(kPi / 6, Vec3::UnitZ()));
    for (double t : {-1.0, 0.0, 0.2, 0.25, 1.0, 1.999, 2.0, 5.0}) {
        const int64_t ns = static_cast<int64_t>(std::llround(t * 1e9));
        const PoseResult r = device->pose(0, ns);
        ASSERT_TRUE(r.ok()) << r.message;
        const double moved = std::clamp(ns * 1e-9, 0.0, 2.0);
        EXPECT_LT((r.sample.pose.position - (start + v * moved)).norm(), 1e-12) << "t=" << t;
        EXPECT_LT(angleBetween(r.sample.pose.orientation, q), 1e-12) << "t=" << t;
        const bool moving = t >= 0 && t < 2;
        EXPECT_EQ(r.sample.linear_velocity, moving ? v : Vec3::Zero()) << "t=" << t;
        EXPECT_EQ(r.sample.angular_velocity, Vec3::Zero());
        EXPECT_EQ(device->controls(ns).state.buttons, t >= 0.25 ? 1u : 0u) << "t=" << t;
    }
    // Velocity against a central difference of the reported positions.
    const Vec3 diff = (device->pose(0, 1'000'001'000).sample.pose.position -
                       device->pose(0, 999'999'000).sample.pose.position) / 2e-6;
    EXPECT_LT((diff - v).norm(), 1e-6);
}

TEST(AnalyticPlugin, LineDefaultsAndLineOnlyOptions) {
    auto host = makeTestHost();
    // Defaults: at rest at the centre, identity orientation, button held from t = 0.
    auto rest = host->open("analytic", "motion=line");
    const PoseResult r = rest->pose(0, 3'000'000'000);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.sample.pose.position, Vec3(0, 0, 1.2));
    EXPECT_EQ(r.sample.pose.orientation.coeffs(), Quat::Identity().coeffs());
    EXPECT_EQ(rest->controls(0).state.buttons, 1u);
    // The line's options exist only for a line; a bad quaternion is named.
    EXPECT_THROW(host->open("analytic", "motion=circle,vx=1"), InputError);
    try {
        host->open("analytic", "motion=line,qw=0.5");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("options qx,qy,qz,qw: expected a unit quaternion [x, y, z, w] (norm 0.5"),
                  std::string::npos) << e.what();
    }
}

TEST(AnalyticPlugin, NoiseIsDeterministicAndBounded) {
    auto host = makeTestHost();
    auto a = host->open("analytic", "motion=static,noise_pos=0.001,noise_rot=0.001");
    auto b = host->open("analytic", "motion=static,noise_pos=0.001,noise_rot=0.001");
    double sum_sq = 0;
    const int n = 2000;
    for (int i = 0; i < n; ++i) {
        const PoseResult ra = a->pose(0, i * 1'000'000), rb = b->pose(0, i * 1'000'000);
        EXPECT_EQ(ra.sample.pose.position, rb.sample.pose.position);
        const Vec3 e = ra.sample.pose.position - Vec3(0, 0, 1.2);
        EXPECT_LE(e.cwiseAbs().maxCoeff(), 0.001 * std::sqrt(3.0) + 1e-12);
        sum_sq += e.squaredNorm() / 3;
    }
    EXPECT_NEAR(std::sqrt(sum_sq / n), 0.001, 0.0001);  // uniform noise with the asked sd
}

}  // namespace
}  // namespace vroc::plugins::test
