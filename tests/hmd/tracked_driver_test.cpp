// SPDX-License-Identifier: MIT
// Tracked bodies driven by devices (TrackedDriver) on the native backend: the `--track` option's
// syntax; a tracked paddle driven by the analytic `line` in `vroc play` is at the analytic pose at
// every frame (the device's velocities, or the fitted ones from the third sample on); a paddle
// named in the scene (`tracking.device`) bats a resting ball away at (1 + e) times its speed; and
// `vroc run --track` drives it from a device where plain `vroc run` uses the file velocity.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "../tools/subprocess.h"
#include "test_backends.h"
#include "vroc/core/errors.h"
#include "vroc/play/play_loop.h"
#include "vroc/play/tracked_driver.h"

namespace vroc::play {
namespace {

namespace fs = std::filesystem;

TEST(TrackOption, ParsesBodySpecAndSensor) {
    const TrackOverride a = parseTrackOption("paddle=analytic:motion=line,vx=1#2");
    EXPECT_EQ(a.body, "paddle");
    EXPECT_EQ(a.source.device, "analytic:motion=line,vx=1");
    EXPECT_EQ(a.source.sensor, 2);
    const TrackOverride b = parseTrackOption("cup=udp:port=4242");
    EXPECT_EQ(b.body, "cup");
    EXPECT_EQ(b.source.device, "udp:port=4242");
    EXPECT_EQ(b.source.sensor, 0);
    for (const char* bad : {"paddle", "=udp", "paddle=", "paddle=udp#", "paddle=udp#-1", "paddle=udp#x", "paddle=#1"})
        EXPECT_THROW(parseTrackOption(bad), InputError) << bad;
}

// A floor (top z = 0), a ball (r = 5 cm, 0.2 kg) resting on it at the origin and a tracked paddle
// (4 x 40 x 20 cm) 0.3 m behind it; frictionless, restitution 0.5. PADDLE_EXTRA is spliced into
// the paddle (a file velocity, a tracking source).
std::string batScene(const std::string& paddle_extra) {
    return R"({
  "format": "vroc-scene/1", "name": "bat", "gravity": [0, 0, -9.81], "frame_dt": 0.016666666666666666,
  "collision_distance": 0.001,
  "materials": {"slick": {"restitution": 0.5, "friction": 0.0}},
  "bodies": [
    {"name": "floor", "role": "real", "material": "slick", "shape": {"box": {"half_extents": [3, 3, 0.1]}},
     "position": [0, 0, -0.1]},
    {"name": "ball", "role": "virtual", "material": "slick", "mass": 0.2, "shape": {"sphere": {"radius": 0.05}},
     "position": [0, 0, 0.0505]},
    {"name": "paddle", "role": "tracked", "material": "slick", "shape": {"box": {"half_extents": [0.02, 0.2, 0.1]}},
     "position": [-0.3, 0, 0.11])" + paddle_extra + R"(}
  ]
})";
}

std::string writeScene(const fs::path& dir, const std::string& text) {
    fs::create_directories(dir);
    const std::string path = (dir / "bat.json").string();
    std::ofstream(path) << text;
    return path;
}

TEST(TrackedDriver, PaddleFollowsTheAnalyticLineInPlay) {
    test::registerBackendsOnce();
    const fs::path dir = fs::path(VROC_BINARY_DIR) / "tracked_follow_test_out";
    fs::remove_all(dir);
    const std::string scene = writeScene(dir, batScene(""));
    // High above the ball, moving at (0.6, 0.1, 0.2) m/s with a fixed 74 deg turn about z.
    const Vec3 start(-1.0, 0.5, 1.0), v(0.6, 0.1, 0.2);
    const Quat q(0.8, 0.0, 0.0, 0.6);   // (w, x, y, z)
    const std::string line = "analytic:motion=line,x=-1,y=0.5,z=1,vx=0.6,vy=0.1,vz=0.2,qz=0.6,qw=0.8";
    for (const bool device_velocities : {true, false}) {
        PlayOptions o;
        o.scene_path = scene;
        o.backend = "native";
        o.frames = 30;
        o.eye_width = 32;
        o.eye_height = 24;
        o.track = {parseTrackOption("paddle=" + line + (device_velocities ? "" : ",velocities=0"))};
        double worst = 0, worst_angle = 0;
        o.on_frame = [&](int i, const Backend& backend) {
            const Pose p = backend.bodyState(2).pose;
            // Without the device's velocities the fit needs three samples: before that the paddle
            // is set at each sample and stands still for the frame.
            const int n = (!device_velocities && i < 2) ? i : i + 1;
            worst = std::max(worst, (p.position - (start + v * (n * (1.0 / 60.0)))).norm());
            worst_angle = std::max(worst_angle, p.orientation.angularDistance(q));
        };
        const PlayReport r = runPlay(o);
        std::printf("device velocities %d: paddle off the analytic line by at most %.2e m, %.2e rad\n",
                    device_velocities, worst, worst_angle);
        // The device is read at round(t 1e9) ns: up to 0.5 ns x 0.64 m/s = 3.2e-10 m off the exact t.
        EXPECT_LT(worst, 0.5e-9 * v.norm() + 1e-12);
        EXPECT_LT(worst_angle, 1e-12);
        ASSERT_EQ(r.tracked.size(), 1u);
        EXPECT_EQ(r.tracked[0].body, "paddle");
        EXPECT_EQ(r.tracked[0].frames_set, 30);
        EXPECT_EQ(r.tracked[0].frames_without_sample, 0);
        EXPECT_EQ(r.tracked[0].velocities_estimated, device_velocities ? 0 : 30);
    }
    fs::remove_all(dir);
}

TEST(TrackedDriver, PaddleFromTheSceneBatsARestingBallAway) {
    // The scene names the paddle's device: play uses it. The paddle (infinite mass) hits the
    // resting ball head on at 2 m/s; frictionless, e = 0.5: the ball leaves at (1 + e) 2 = 3 m/s.
    test::registerBackendsOnce();
    const fs::path dir = fs::path(VROC_BINARY_DIR) / "tracked_bat_test_out";
    fs::remove_all(dir);
    const std::string scene = writeScene(
        dir, batScene(R"(, "tracking": {"device": "analytic:motion=line,x=-0.3,y=0,z=0.11,vx=2"})"));
    PlayOptions o;
    o.scene_path = scene;
    o.backend = "native";
    o.frames = 30;
    o.eye_width = 32;
    o.eye_height = 24;
    Vec3 ball_v = Vec3::Zero();
    double ball_z_min = 1;
    o.on_frame = [&](int, const Backend& backend) {
        ball_v = backend.bodyState(1).linear_velocity;
        ball_z_min = std::min(ball_z_min, backend.bodyState(1).pose.position.z());
    };
    const PlayReport r = runPlay(o);
    ASSERT_EQ(r.tracked.size(), 1u);
    EXPECT_EQ(r.tracked[0].device, "analytic:motion=line,x=-0.3,y=0,z=0.11,vx=2");
    std::printf("ball after the hit: v = (%.6f, %.6f, %.6f) m/s; warnings %zu\n", ball_v.x(), ball_v.y(), ball_v.z(),
                r.warnings.size());
    EXPECT_NEAR(ball_v.x(), 3.0, 1e-6);
    EXPECT_NEAR(ball_v.y(), 0.0, 1e-9);
    EXPECT_GT(ball_z_min, 0.05 - 1e-3);   // never pushed into the floor
    fs::remove_all(dir);
}

/// The ball's velocity at the last row of trajectory.csv.
Vec3 lastBallVelocity(const fs::path& run_dir) {
    const std::vector<std::string> lines = test::splitLines(test::readText((run_dir / "trajectory.csv").string()));
    for (auto it = lines.rbegin(); it != lines.rend(); ++it) {
        const test::CsvRow row = test::splitCsv(*it);
        if (row.size() == 15 && row[1] == "ball") return {std::stod(row[9]), std::stod(row[10]), std::stod(row[11])};
    }
    ADD_FAILURE() << "no ball row in " << run_dir;
    return Vec3::Zero();
}

TEST(TrackedDriver, VrocRunTrackOverridesTheFileVelocity) {
    // Plain `vroc run` moves the paddle at its file velocity (2 m/s: the ball leaves at 3 m/s);
    // `--track` drives it from a device instead (1 m/s: 1.5 m/s). The scene's own tracking.device
    // (4 m/s) is ignored by `vroc run`: the harness's runs stay deterministic.
    const fs::path dir = fs::path(VROC_BINARY_DIR) / "tracked_run_test_out";
    fs::remove_all(dir);
    const std::string scene = writeScene(
        dir, batScene(R"(, "linear_velocity": [2, 0, 0], "tracking": {"device": "analytic:motion=line,x=-0.3,z=0.11,vx=4"})"));
    const test::ProcessResult plain =
        test::runVroc({"run", scene, "--backend", "native", "--duration", "0.5", "--out", "plain", "-q"}, dir);
    ASSERT_EQ(plain.exit_code, 0) << plain.err;
    EXPECT_NEAR(lastBallVelocity(dir / "plain").x(), 3.0, 1e-6);
    const test::ProcessResult tracked = test::runVroc(
        {"run", scene, "--backend", "native", "--duration", "0.5", "--out", "tracked", "-q", "--track",
         "paddle=analytic:motion=line,x=-0.3,y=0,z=0.11,vx=1"},
        dir);
    ASSERT_EQ(tracked.exit_code, 0) << tracked.err;
    EXPECT_NEAR(lastBallVelocity(dir / "tracked").x(), 1.5, 1e-6);
    // Bad input: a body that is not tracked, a missing plugin.
    const test::ProcessResult not_tracked =
        test::runVroc({"run", scene, "--backend", "native", "--out", "bad", "--track", "ball=analytic"}, dir);
    EXPECT_EQ(not_tracked.exit_code, 2);
    EXPECT_NE(not_tracked.err.find("is not tracked"), std::string::npos) << not_tracked.err;
    EXPECT_FALSE(fs::exists(dir / "bad" / "run.json"));
    const test::ProcessResult no_plugin =
        test::runVroc({"run", scene, "--backend", "native", "--out", "bad", "--track", "paddle=no-such-plugin"}, dir);
    EXPECT_EQ(no_plugin.exit_code, 2) << no_plugin.err;
    fs::remove_all(dir);
}

}  // namespace
}  // namespace vroc::play
