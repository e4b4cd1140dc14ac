// SPDX-License-Identifier: MIT
// `vroc play`'s loop end to end on the staircase: frames and play.json written, the analytic
// throw grabs ball_0 and throws it at the device's speed, and the registration statistics of the
// scripted head follow its closed-form bound (error <= yaw rate x latency, prediction helps).
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_backends.h"
#include "vroc/play/play_loop.h"
#include "vroc/play/scripted_head.h"
#include "vroc/render/image.h"

namespace vroc::play {
namespace {

TEST(PlayLoop, StaircaseThrowFramesAndReport) {
    test::registerBackendsOnce();
    const std::string out = std::string(VROC_BINARY_DIR) + "/play_loop_test_out";
    std::filesystem::remove_all(out);
    PlayOptions o;
    o.scene_path = std::string(VROC_SOURCE_DIR) + "/scenes/staircase.json";
    o.backend = "bullet";
    // ball_0 starts at (0.10, -0.30, 1.25): the throw arc's hand starts 0.6 m behind its centre.
    o.device_spec = "analytic:motion=throw,x=0.7,y=-0.3,z=1.25,radius=0.6,throw_speed=3";
    o.frames = 60;
    o.eye_width = 320;
    o.eye_height = 240;
    o.out_dir = out;
    const PlayReport r = runPlay(o);
    writePlayJson(r, out + "/play.json");

    ASSERT_EQ(r.grabs, 1);
    ASSERT_EQ(r.throws.size(), 1u);
    EXPECT_EQ(r.body_names[r.throws[0].body], "ball_0");
    const ThrowRecord& t = r.throws[0];
    ASSERT_TRUE(t.device_velocity_known);
    EXPECT_LT((t.linear_velocity - t.device_linear_velocity).norm(), 0.03 * t.device_linear_velocity.norm());

    // Registration: the scripted head's peak yaw rate bounds the error of the delayed pose
    // (rate x 50 ms latency + the 60 Hz tracker grid), and both predictors do better.
    const ScriptedHead head;
    const double peak_deg_per_s = head.yaw_amplitude * 2 * M_PI * head.yaw_frequency * 180 / M_PI +
                                  head.pitch_amplitude * 2 * M_PI * head.pitch_frequency * 180 / M_PI;
    const double bound = peak_deg_per_s * (0.050 + 1.0 / 60.0);
    EXPECT_GT(r.registration.at("none").max, 0.2);
    EXPECT_LT(r.registration.at("none").max, bound);
    EXPECT_LT(r.registration.at("constant-velocity").mean, 0.5 * r.registration.at("none").mean);
    EXPECT_LT(r.registration.at("kalman").mean, 0.5 * r.registration.at("none").mean);

    // Files: 60 frames of 640 x 240 and a play.json that says the same as the report.
    const render::Image last = render::readPng(out + "/frame_00059.png");
    EXPECT_EQ(last.width, 640);
    EXPECT_EQ(last.height, 240);
    EXPECT_FALSE(std::filesystem::exists(out + "/frame_00060.png"));
    std::ifstream in(out + "/play.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    EXPECT_EQ(j["format"], "vroc-play/1");
    EXPECT_EQ(j["frames"], 60);
    EXPECT_EQ(j["throws"].size(), 1u);
    EXPECT_EQ(j["throws"][0]["body"], "ball_0");
    EXPECT_GT(j["rates_fps"]["render"].get<double>(), 0.0);
    EXPECT_DOUBLE_EQ(j["latency_model_ms"]["total"].get<double>(), 50.0);
    std::filesystem::remove_all(out);
}

}  // namespace
}  // namespace vroc::play
