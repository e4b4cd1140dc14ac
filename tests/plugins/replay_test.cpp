// SPDX-License-Identifier: MIT
// Record analytic motion with PoseRecorder, replay it, compare with the closed form.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <fstream>

#include "plugin_test_host.h"
#include "vroc/core/errors.h"
#include "vroc/plugin/pose_recorder.h"

namespace vroc::plugins::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The figure-eight of the analytic plugin (radius r, period T, centre (0,0,1.2)), recomputed.
struct FigureEight {
    double r = 0.3, period = 2.0;
    Vec3 position(double t) const {
        const double a = 2 * kPi / period * t;
        return Vec3(r * std::sin(a), 0.5 * r * std::sin(2 * a), 1.2);
    }
    Quat orientation(double t) const {
        return Quat(Eigen::AngleAxisd(0.5 * std::sin(2 * kPi / period * t), Vec3::UnitX()));
    }
    double maxAcceleration() const {  // |p''| <= r w^2 + 2 r w^2 (x and y parts)
        const double w = 2 * kPi / period;
        return std::sqrt(std::pow(r * w * w, 2) + std::pow(2 * r * w * w, 2));
    }
};

// Each test writes its own file: CTest runs the tests of this suite in parallel processes.
std::string recordFigureEight(PluginHost& host, int64_t step_ns, int samples) {
    const std::string path = ::testing::TempDir() + "vroc_replay_" +
                             ::testing::UnitTest::GetInstance()->current_test_info()->name() + "_" +
                             std::to_string(getpid()) + ".csv";
    auto source = host.open("analytic", "motion=figure8,radius=0.3,period=2");
    PoseRecorder recorder(path);
    for (int i = 0; i < samples; ++i) {
        const PoseResult r = source->pose(0, i * step_ns);
        EXPECT_TRUE(r.ok());
        recorder.add(r.sample, static_cast<uint64_t>(i % 3 == 0));
    }
    recorder.close();
    EXPECT_EQ(recorder.rows(), static_cast<uint64_t>(samples));
    return path;
}

TEST(ReplayPlugin, RoundTripMatchesAnalyticMotionAtAndBetweenSamples) {
    auto host = makeTestHost();
    const int64_t step = 10'000'000;  // 100 Hz
    const std::string path = recordFigureEight(*host, step, 201);
    auto replay = host->open("replay", "file=" + path);
    const FigureEight truth;
    // At the samples: exact (17 significant digits round-trip).
    for (int i = 0; i <= 200; i += 7) {
        const PoseResult r = replay->pose(0, i * step);
        ASSERT_TRUE(r.ok()) << r.message;
        EXPECT_LT((r.sample.pose.position - truth.position(i * step * 1e-9)).norm(), 1e-14);
        EXPECT_LT(angleBetween(r.sample.pose.orientation, truth.orientation(i * step * 1e-9)), 1e-7);
        EXPECT_TRUE(r.sample.has(VROC_POSE_POSITION_TRACKED));
    }
    // Between samples: linear interpolation error <= |p''|max h^2 / 8; slerp on a single-axis
    // rotation interpolates the angle linearly, error <= |theta''|max h^2 / 8.
    const double h = 0.01, w = 2 * kPi / 2.0;
    const double position_bound = truth.maxAcceleration() * h * h / 8;
    const double angle_bound = 0.5 * w * w * h * h / 8;
    double worst_position = 0;
    for (int i = 0; i < 200; i += 3) {
        for (double f : {0.25, 0.5, 0.8}) {
            const int64_t t = i * step + static_cast<int64_t>(f * step);
            const PoseResult r = replay->pose(0, t);
            ASSERT_TRUE(r.ok());
            const double p_error = (r.sample.pose.position - truth.position(t * 1e-9)).norm();
            worst_position = std::max(worst_position, p_error);
            EXPECT_LE(p_error, position_bound * 1.0001) << "t_ns=" << t;
            EXPECT_LE(angleBetween(r.sample.pose.orientation, truth.orientation(t * 1e-9)), angle_bound * 1.0001 + 1e-9)
                << "t_ns=" << t;
            // Midway the position is exactly the mean of the two recorded samples.
            if (f == 0.5) {
                const Vec3 mean = 0.5 * (truth.position(i * 0.01) + truth.position((i + 1) * 0.01));
                EXPECT_LT((r.sample.pose.position - mean).norm(), 1e-12);
            }
        }
    }
    EXPECT_GT(worst_position, position_bound * 0.05);  // really interpolating, not sampling truth
    // Buttons come from the sample at or before the time.
    EXPECT_EQ(replay->controls(3 * step + 5).state.buttons, 1u);
    EXPECT_EQ(replay->controls(4 * step + 5).state.buttons, 0u);
}

TEST(ReplayPlugin, HoldsEndsUntrackedAndLoops) {
    auto host = makeTestHost();
    const int64_t step = 10'000'000;
    const std::string path = recordFigureEight(*host, step, 101);
    auto replay = host->open("replay", "file=" + path);
    const PoseResult after = replay->pose(0, 5'000'000'000);
    ASSERT_TRUE(after.ok());
    EXPECT_EQ(after.code, VROC_EXTRAPOLATED);
    EXPECT_FALSE(after.sample.has(VROC_POSE_POSITION_TRACKED));
    EXPECT_LT((after.sample.pose.position - FigureEight().position(1.0)).norm(), 1e-15);
    EXPECT_EQ(replay->pose(1, 0).status, SampleStatus::NoData);

    auto looped = host->open("replay", "loop=1,file=" + path);
    const PoseResult r = looped->pose(0, 1'000'000'000 + 25 * step);
    EXPECT_LT((r.sample.pose.position - FigureEight().position(0.25)).norm(), 1e-15);
}

// Found by tests/fuzz/pose_csv_fuzz (docs/fuzzing.md): two samples 1.2e19 ns apart, more than an
// int64 holds. The span and the loop length overflowed (signed overflow: undefined; in practice a
// negative span, so the position went backwards and looping stopped).
TEST(ReplayPlugin, RecordingSpanningMoreThanTheInt64RangeInterpolatesAndLoops) {
    const std::string path = ::testing::TempDir() + "vroc_replay_span_" + std::to_string(getpid()) + ".csv";
    {
        std::ofstream out(path);
        out << "time_ns,sensor,x,y,z,qx,qy,qz,qw,buttons\n"
               "-8000000000000000000,0,0,0,0,0,0,0,1,0\n"
               "4000000000000000000,0,12,0,0,0,0,0,1,0\n";
    }
    auto host = makeTestHost();
    auto replay = host->open("replay", "file=" + path);
    // Host time 0 is 8e18 ns into the 1.2e19 ns between the samples: 2/3 of the way.
    const PoseResult r = replay->pose(0, 0);
    ASSERT_TRUE(r.ok()) << r.message;
    EXPECT_EQ(r.code, VROC_OK);
    EXPECT_NEAR(r.sample.pose.position.x(), 8.0, 1e-12);
    EXPECT_NEAR(r.sample.linear_velocity.x(), 12.0 / 1.2e10, 1e-22);   // [m/s]
    // Looping: 5e18 is 1.3e19 after the first sample, 1e18 into the second pass (1/12 of the way).
    auto looped = host->open("replay", "loop=1,file=" + path);
    const PoseResult l = looped->pose(0, 5'000'000'000'000'000'000);
    ASSERT_TRUE(l.ok()) << l.message;
    EXPECT_EQ(l.code, VROC_OK);
    EXPECT_NEAR(l.sample.pose.position.x(), 1.0, 1e-12);
}

// Found with tests/fuzz/pose_csv_fuzz (docs/fuzzing.md): positions of 1e308 and -1e308 m were
// accepted, and the pose between them (and its velocity) came out infinite, for the host to reject
// at run time. Positions are now held to +-1e6 m per coordinate when the recording is read.
TEST(ReplayPlugin, PositionBeyondTheAcceptedRangeIsInputErrorWithLine) {
    const std::string path = ::testing::TempDir() + "vroc_replay_far_" + std::to_string(getpid()) + ".csv";
    {
        std::ofstream out(path);
        out << "time_ns,sensor,x,y,z,qx,qy,qz,qw,buttons\n0,0,1e308,0,0,0,0,0,1,0\n10,0,-1e308,0,0,0,0,0,1,0\n";
    }
    auto host = makeTestHost();
    try {
        host->open("replay", "file=" + path);
        FAIL() << "a recording at 1e308 m opened";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(path + ":2: column x: expected a position within +-1e6 m"), std::string::npos)
            << e.what();
    }
}

TEST(ReplayPlugin, MalformedRecordingIsInputErrorWithLine) {
    const std::string path = ::testing::TempDir() + "vroc_replay_bad_" + std::to_string(getpid()) + ".csv";
    {
        std::ofstream out(path);
        out << "time_ns,sensor,x,y,z,qx,qy,qz,qw,buttons\n0,0,0,0,0,0,0,0,1,0\n10,0,0,0,0,0,0,0,2,0\n";
    }
    auto host = makeTestHost();
    try {
        host->open("replay", "file=" + path);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(path + ":3: columns qx..qw: expected a unit quaternion"), std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace vroc::plugins::test
