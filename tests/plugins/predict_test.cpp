// SPDX-License-Identifier: MIT
// Latency hiding: a head turning with 200 deg/s peak rate, tracked at 120 Hz with 50 ms latency.
// The registration error without prediction follows e = w * dt (about 10 deg at the peak); the
// predict plugin must cut it several-fold (Azuma & Bishop 1994 report 5-10x with inertial data).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "plugin_test_host.h"
#include "vroc/core/errors.h"

namespace vroc::plugins::test {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180;

// Closed-form head yaw: amplitude A, peak rate S, so frequency S / (2 pi A).
Quat trueHead(double t, double amplitude = 30 * kDeg, double speed = 200 * kDeg) {
    const double f = speed / (2 * kPi * amplitude);
    return Quat(Eigen::AngleAxisd(amplitude * std::sin(2 * kPi * f * t), Vec3::UnitZ()));
}

struct ErrorStats {
    double rms = 0, max = 0;  // [deg]
};

// Asks `device` for the head pose at display times t (60 Hz over 4 s after 0.5 s warm-up) and
// compares with the true head at t.
ErrorStats registrationError(DeviceHandle& device) {
    double sum_sq = 0;
    int n = 0;
    ErrorStats stats;
    for (int frame = 0; frame < 270; ++frame) {
        const int64_t t = static_cast<int64_t>(frame) * 1'000'000'000 / 60;
        const PoseResult r = device.pose(0, t);
        EXPECT_TRUE(r.ok()) << r.message;
        if (frame < 30) continue;  // filter warm-up
        const double e = angleBetween(r.sample.pose.orientation, trueHead(t * 1e-9)) / kDeg;
        sum_sq += e * e;
        stats.max = std::max(stats.max, e);
        ++n;
    }
    stats.rms = std::sqrt(sum_sq / n);
    return stats;
}

const char* kHead = "inner=analytic,inner.motion=head-turn,inner.speed_deg=200,inner.amplitude_deg=30,"
                    "inner.latency=0.05,inner.rate=120";

TEST(PredictPlugin, NoPredictionGivesTheOmegaTimesLatencyError) {
    auto host = makeTestHost();
    auto device = host->open("predict", std::string(kHead) + ",method=none");
    const ErrorStats none = registrationError(*device);
    // Peak error = 200 deg/s x (50 ms + up to one 8.3 ms sample period), less near the peak
    // because the rate falls off either side.
    EXPECT_GT(none.max, 9.0);
    EXPECT_LT(none.max, 200 * (0.05 + 1.0 / 120));
    std::printf("[ measure  ] head turn 200 deg/s, 50 ms latency, 120 Hz: no prediction rms %.3f max %.3f deg\n",
                none.rms, none.max);
}

TEST(PredictPlugin, PredictionCutsRegistrationErrorSeveralFold) {
    auto host = makeTestHost();
    const ErrorStats none = registrationError(*host->open("predict", std::string(kHead) + ",method=none"));
    const ErrorStats cv = registrationError(*host->open("predict", std::string(kHead) + ",method=cv"));
    const ErrorStats kalman = registrationError(*host->open("predict", std::string(kHead) + ",method=kalman"));
    // Without the tracker's velocities: finite differences / position-only Kalman.
    const std::string no_vel = std::string(kHead) + ",inner.velocities=0";
    const ErrorStats cv_fd = registrationError(*host->open("predict", no_vel + ",method=cv"));
    const ErrorStats kalman_pos = registrationError(*host->open("predict", no_vel + ",method=kalman"));
    std::printf("[ measure  ] rms/max deg: none %.3f/%.3f cv %.3f/%.3f kalman %.3f/%.3f cv(diff) %.3f/%.3f "
                "kalman(no vel) %.3f/%.3f\n",
                none.rms, none.max, cv.rms, cv.max, kalman.rms, kalman.max, cv_fd.rms, cv_fd.max, kalman_pos.rms,
                kalman_pos.max);
    EXPECT_LT(cv.rms, none.rms / 3);
    EXPECT_LT(kalman.rms, none.rms / 3);
    EXPECT_LT(cv_fd.rms, none.rms / 2);
    EXPECT_LT(kalman_pos.rms, none.rms / 2);
    EXPECT_LT(kalman.max, none.max / 3);
}

TEST(PredictPlugin, SameQueriesGiveBitIdenticalPredictions) {
    auto host = makeTestHost();
    const std::string options = std::string(kHead) + ",inner.noise_rot=0.002,inner.noise_pos=0.001,method=kalman";
    auto a = host->open("predict", options);
    auto b = host->open("predict", options);
    for (int frame = 0; frame < 120; ++frame) {
        const int64_t t = static_cast<int64_t>(frame) * 1'000'000'000 / 60;
        const PoseSample sa = a->pose(0, t).sample, sb = b->pose(0, t).sample;
        ASSERT_EQ(sa.pose.position, sb.pose.position) << "frame " << frame;
        ASSERT_EQ(sa.pose.orientation.coeffs(), sb.pose.orientation.coeffs()) << "frame " << frame;
    }
}

TEST(PredictPlugin, AheadOptionPredictsPastTheMeasurementTime) {
    auto host = makeTestHost();
    // Spin at a constant 90 deg/s: constant-velocity prediction is exact.
    auto device = host->open("predict", "inner=analytic,inner.motion=spin,inner.speed_deg=90,inner.latency=0.05,"
                                        "method=cv,ahead=0.03");
    const PoseResult r = device->pose(0, 2'000'000'000);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.sample.time_ns, 2'000'000'000 - 50'000'000 + 30'000'000);
    const Quat expected(Eigen::AngleAxisd(90 * kDeg * 1.98, Vec3::UnitZ()));
    EXPECT_LT(angleBetween(r.sample.pose.orientation, expected), 1e-9);
    EXPECT_TRUE(r.sample.has(VROC_POSE_EXTRAPOLATED));
}

TEST(PredictPlugin, MissingOrBrokenInnerIsAClearOpenError) {
    auto host = makeTestHost();
    EXPECT_THROW(host->open("predict", "method=cv"), InputError);
    try {
        host->open("predict", "inner=nothing-here");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("predict: cannot load inner plugin 'nothing-here'"), std::string::npos)
            << e.what();
    }
    try {
        host->open("predict", "inner=analytic,inner.motion=zigzag");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("predict: inner analytic: analytic: option motion='zigzag'"),
                  std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace vroc::plugins::test
