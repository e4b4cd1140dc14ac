// SPDX-License-Identifier: MIT
// recordRun with a test backend whose motion is known in closed form (free flight), so every
// recorded number can be checked against an independent formula, plus its failure paths.
#include <cmath>
#include <filesystem>
#include <limits>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "csv_reader.h"
#include "test_scenes.h"
#include "vroc/core/errors.h"
#include "vroc/core/recording/run_recorder.h"
#include "vroc/core/scene_loader.h"
#include "vroc/core/state_hash.h"

namespace vroc::recording {
namespace {
namespace fs = std::filesystem;

// Free flight under gravity, integrated exactly per frame (semi-analytic), no contacts. Emits one
// event between the first two bodies every 10th frame; can fail at a chosen frame.
class FlightBackend final : public Backend {
public:
    FlightBackend(const Scene& scene, const Settings& settings)
        : scene_(scene), fail_at_(settings.integer("flight.fail_at_frame")) {
        for (const auto& body : scene.bodies) states_.push_back({body.pose, body.linear_velocity, body.angular_velocity});
    }
    void stepFrame(double dt) override {
        ++frame_;
        if (frame_ == fail_at_) throw RunError("flight: failing at frame " + std::to_string(frame_) + " as asked");
        time_ = static_cast<double>(frame_) * dt;
        for (std::size_t i = 0; i < states_.size(); ++i) {
            const Body& b = scene_.bodies[i];
            if (b.isStatic()) continue;
            states_[i].pose.position = b.pose.position + b.linear_velocity * time_ + 0.5 * scene_.gravity * time_ * time_;
            states_[i].linear_velocity = b.linear_velocity + scene_.gravity * time_;
        }
        if (frame_ % 10 == 0) events_.push_back({time_, 0, 1, Vec3(0, 0, 0), Vec3(0, 0, 1), 0.5 * frame_});
    }
    double time() const override { return time_; }
    int bodyCount() const override { return static_cast<int>(states_.size()); }
    BodyState bodyState(int body) const override { return states_.at(body); }
    void setBodyState(int body, const BodyState& state) override { states_.at(body) = state; }
    void applyImpulse(int, const Vec3&, const Vec3&) override {}
    std::vector<CollisionEvent> takeEvents() override { return std::exchange(events_, {}); }
    WarningCounts warnings() const override { return {{"none_really", 0}}; }
    Statistics statistics() const override { return {{"frames", static_cast<double>(frame_)}}; }

private:
    const Scene& scene_;
    std::int64_t fail_at_;
    std::int64_t frame_ = 0;
    double time_ = 0;
    std::vector<BodyState> states_;
    std::vector<CollisionEvent> events_;
};

BackendInfo flightInfo() {
    BackendInfo info;
    info.name = "flight";
    info.description = "test: exact free flight";
    info.version = "flight 1";
    SettingSpec fail;
    fail.key = "flight.fail_at_frame";
    fail.type = SettingSpec::Type::Integer;
    fail.default_value = "-1";
    fail.min = -1;
    fail.help = "frame at which stepFrame throws (-1: never)";
    info.settings = {fail};
    info.create = [](const Scene& scene, const Settings& settings) -> std::unique_ptr<Backend> {
        return std::make_unique<FlightBackend>(scene, settings);
    };
    return info;
}

struct RunRecorder : ::testing::Test {
    void SetUp() override {
        dir = test::freshTempDir(::testing::UnitTest::GetInstance()->current_test_info()->name());
        scene = loadSceneFromString(test::kTwoBodyScene, "two_bodies.json");
        info = flightInfo();
        request.scene = &scene;
        request.backend = &info;
        request.settings = resolveSettings(info.settings, {});
        request.frame_dt = 0.01;
        request.duration = 0.5;
        request.out_dir = dir / "out";
    }
    void TearDown() override { fs::remove_all(dir); }
    fs::path dir;
    Scene scene;
    BackendInfo info;
    RunRequest request;
};

TEST_F(RunRecorder, RecordsClosedFormFlightFrameByFrame) {
    const RunRecord record = recordRun(request);
    EXPECT_EQ(record.steps, 50);
    const auto lines = test::splitLines(test::readText((request.out_dir / "trajectory.csv").string()));
    ASSERT_EQ(lines.size(), 1u + 2u * 51u);
    for (std::size_t row = 1; row < lines.size(); ++row) {
        const auto f = test::splitCsv(lines[row]);
        const int frame = static_cast<int>((row - 1) / 2);
        const Body& body = scene.bodies[f[1] == "ball" ? 1 : 2];
        EXPECT_EQ(f[1], (row - 1) % 2 == 0 ? "ball" : "box");
        const double t = frame * 0.01;
        ASSERT_EQ(std::stod(f[0]), t) << lines[row];
        for (int k = 0; k < 3; ++k) {
            const double x = body.pose.position[k] + body.linear_velocity[k] * t + 0.5 * scene.gravity[k] * t * t;
            EXPECT_NEAR(std::stod(f[2 + k]), x, 1e-15 * (1 + std::abs(x))) << lines[row];
            EXPECT_NEAR(std::stod(f[9 + k]), body.linear_velocity[k] + scene.gravity[k] * t, 1e-14) << lines[row];
            EXPECT_EQ(std::stod(f[12 + k]), body.angular_velocity[k]) << lines[row];
        }
        EXPECT_EQ(std::stod(f[5]), body.pose.orientation.x());
        EXPECT_EQ(std::stod(f[8]), body.pose.orientation.w());
    }
    const auto events = test::splitLines(test::readText((request.out_dir / "events.csv").string()));
    ASSERT_EQ(events.size(), 1u + 5u);   // frames 10, 20, ..., 50
    EXPECT_EQ(test::splitCsv(events[5])[9], "25");
    EXPECT_EQ(record.collision_count, 5u);
    EXPECT_EQ(record.pair_count, 1u);
}

TEST_F(RunRecorder, RunJsonHoldsTheRecordAndTheFinalStateHash) {
    const RunRecord record = recordRun(request);
    const auto j = nlohmann::json::parse(test::readText((request.out_dir / "run.json").string()));
    EXPECT_EQ(j["backend"]["name"], "flight");
    EXPECT_EQ(j["settings"]["flight.fail_at_frame"], "-1");
    EXPECT_EQ(j["steps"], 50);
    EXPECT_EQ(j["statistics"]["frames"], 50.0);
    // The hash of the closed-form final state, computed here independently of the recorder.
    std::vector<BodyState> final_states;
    for (const Body& b : scene.bodies) {
        BodyState s{b.pose, b.linear_velocity, b.angular_velocity};
        if (!b.isStatic()) {
            const double t = 50 * 0.01;
            s.pose.position = b.pose.position + b.linear_velocity * t + 0.5 * scene.gravity * t * t;
            s.linear_velocity = b.linear_velocity + scene.gravity * t;
        }
        final_states.push_back(s);
    }
    EXPECT_EQ(j["state_hash"], hashToHex(stateHash(final_states)));
    EXPECT_EQ(record.state_hash, j["state_hash"]);
    for (const char* name : {"trajectory.csv.tmp", "events.csv.tmp", "run.json.tmp"})
        EXPECT_FALSE(fs::exists(request.out_dir / name)) << name;
}

TEST_F(RunRecorder, FailureWhileSteppingLeavesNothingThatLooksComplete) {
    request.settings = resolveSettings(info.settings, {{"flight.fail_at_frame", "20"}});
    EXPECT_THROW(recordRun(request), RunError);
    EXPECT_FALSE(fs::exists(request.out_dir));   // it created the directory, so it removed it
}

TEST_F(RunRecorder, FailureInAnExistingDirectoryKeepsItButWithoutRunJson) {
    fs::create_directories(request.out_dir);
    test::writeFile(request.out_dir / "run.json", "{\"old\": true}");
    test::writeFile(request.out_dir / "notes.txt", "user file");
    request.settings = resolveSettings(info.settings, {{"flight.fail_at_frame", "3"}});
    EXPECT_THROW(recordRun(request), RunError);
    EXPECT_FALSE(fs::exists(request.out_dir / "run.json"));
    EXPECT_TRUE(fs::exists(request.out_dir / "notes.txt"));
    EXPECT_FALSE(fs::exists(request.out_dir / "trajectory.csv.tmp"));
}

TEST_F(RunRecorder, FrameCountRoundsOnlyFloatingNoise) {
    EXPECT_EQ(frameCount(5.0, 1.0 / 60.0), 300);
    EXPECT_EQ(frameCount(1.0, 0.3), 4);    // 3.33 frames: round up to cover the duration
    EXPECT_EQ(frameCount(0.3, 0.1), 3);    // 2.9999999999999996 is floating noise
    EXPECT_EQ(frameCount(0.001, 0.1), 1);
    for (double bad : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
        EXPECT_THROW(frameCount(bad, 0.01), InputError) << bad;
        EXPECT_THROW(frameCount(1.0, bad), InputError) << bad;
    }
    EXPECT_THROW(frameCount(1e8, 1e-3), InputError);   // 1e11 frames
}

TEST_F(RunRecorder, InterruptionByProgressCallbackIsARunError) {
    request.progress = [](std::int64_t done, std::int64_t) { return done < 7; };
    EXPECT_THROW(recordRun(request), RunError);
    EXPECT_FALSE(fs::exists(request.out_dir));
}

}  // namespace
}  // namespace vroc::recording
