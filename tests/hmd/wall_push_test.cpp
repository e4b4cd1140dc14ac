// SPDX-License-Identifier: MIT
// Force output end to end on the native backend, through the real loader and the real `force-log`
// plugin wrapping the analytic `line` hand: a held box pushed at constant speed into a real wall
// stops at the wall (the contacts hold it out) while the hand goes on, and the force sent to the
// hand is the coupling's reaction, k x (hand target - box position) along the normal (plus the
// damper's c x hand speed while the hand still moves); and a held ball dragged down the paper's
// staircase, pressed into treads and over an edge, never sinks into a step.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "staircase_geometry.h"
#include "test_backends.h"
#include "vroc/play/play_loop.h"

namespace vroc::play {
namespace {

namespace fs = std::filesystem;

struct ForceRow {
    std::int64_t time_ns = 0;
    Vec3 force = Vec3::Zero(), torque = Vec3::Zero();
};

/// The force-log CSV (time_ns, sensor, fx, fy, fz, tx, ty, tz).
std::vector<ForceRow> readForceLog(const std::string& path) {
    std::ifstream in(path);
    EXPECT_TRUE(in.good()) << path;
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "time_ns,sensor,fx,fy,fz,tx,ty,tz");
    std::vector<ForceRow> rows;
    while (std::getline(in, line)) {
        std::replace(line.begin(), line.end(), ',', ' ');
        std::istringstream fields(line);
        ForceRow r;
        int sensor = -1;
        fields >> r.time_ns >> sensor >> r.force.x() >> r.force.y() >> r.force.z() >> r.torque.x() >> r.torque.y() >>
            r.torque.z();
        EXPECT_FALSE(fields.fail()) << line;
        EXPECT_EQ(sensor, 0);
        rows.push_back(r);
    }
    return rows;
}

std::uint64_t warningCount(const WarningCounts& warnings, const std::string& suffix) {
    std::uint64_t n = 0;
    for (const auto& [name, count] : warnings)
        if (name.size() >= suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0) n += count;
    return n;
}

// A 10 cm, 1 kg box at (0, 0, 1) and a real wall whose face is the plane x = 0.45, frictionless: the
// normal force is then the only contact force, as in the closed form. (With friction 0.5 the
// native backend tumbles the pressed box: the gravity compensation, an impulse at each frame start,
// makes the box slide up and down the wall within each frame, and the friction impulse of the
// per-frame collision acts at the patch centroid, 5 cm from the centre, spinning it; Bullet instead
// lets the box 8 mm into the wall at the first touch. Both are backend matters, noted in docs/hmd.md.)
constexpr const char* kWallScene = R"({
  "format": "vroc-scene/1", "name": "wall-push", "gravity": [0, 0, -9.81], "frame_dt": 0.016666666666666666,
  "collision_distance": 0.001,
  "materials": {"ice": {"restitution": 0.0, "friction": 0.0}},
  "bodies": [
    {"name": "wall", "role": "real", "material": "ice", "shape": {"box": {"half_extents": [0.05, 0.5, 0.5]}},
     "position": [0.5, 0, 1.0]},
    {"name": "box", "role": "virtual", "material": "ice", "mass": 1.0,
     "shape": {"box": {"half_extents": [0.05, 0.05, 0.05]}}, "position": [0, 0, 1.0]}
  ]
})";

TEST(WallPush, CouplingForceIsStiffnessTimesHandPenetration) {
    test::registerBackendsOnce();
    const fs::path dir = fs::path(VROC_BINARY_DIR) / "wall_push_test_out";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string scene_path = (dir / "wall.json").string(), log_path = (dir / "forces.csv").string();
    std::ofstream(scene_path) << kWallScene;

    // The hand starts on the box and moves at 0.5 m/s along +x for 1.2 s (to x = 0.6), button held;
    // the box meets the wall (at x = 0.40) near t = 0.8 s and stays there.
    const double speed = 0.5, duration = 1.2, half = 0.05, face = 0.45, dt = 1.0 / 60.0;
    PlayOptions o;
    o.scene_path = scene_path;
    o.backend = "native";
    o.device_spec = "force-log:out=" + log_path +
                    ",inner=analytic,inner.motion=line,inner.x=0,inner.y=0,inner.z=1,inner.vx=0.5,inner.duration=1.2";
    o.frames = 120;
    o.eye_width = 32;
    o.eye_height = 24;
    std::vector<Vec3> box_at = {Vec3(0, 0, 1.0)};   // box centre at t_i = i dt
    o.on_frame = [&](int, const Backend& backend) { box_at.push_back(backend.bodyState(1).pose.position); };
    const PlayReport r = runPlay(o);

    ASSERT_EQ(r.grabs, 1);
    EXPECT_TRUE(r.hand_accepts_force);
    EXPECT_EQ(r.forces_sent, 120);   // held from the first frame to the last
    EXPECT_EQ(r.forces_rejected, 0);
    EXPECT_EQ(warningCount(r.warnings, "penetration_recovered"), 0u);
    const std::vector<ForceRow> rows = readForceLog(log_path);
    ASSERT_EQ(rows.size(), 120u);

    // The box never goes into the wall by more than the collision distance.
    double deepest = -1;
    for (const Vec3& p : box_at) deepest = std::max(deepest, p.x() + half - face);
    EXPECT_LT(deepest, 1e-3);

    // k = m w^2, c = 2 zeta m w for the 1 kg box at the default 5 Hz, zeta = 1.
    const double w = 2 * M_PI * 5.0, k = w * w, c = 2 * w;
    double worst_moving = 0, worst_still = 0, last_force = 0, last_penetration = 0;
    int resting_moving = 0, resting_still = 0;
    for (std::size_t n = 0; n < rows.size(); ++n) {
        const int i = static_cast<int>(std::llround(static_cast<double>(rows[n].time_ns) * 1e-9 / dt));
        ASSERT_EQ(i, static_cast<int>(n)) << "one force per frame, at the frame's time";
        if (i < 1) continue;
        const double t = i * dt;
        const bool resting = std::abs(box_at[i].x() - box_at[i - 1].x()) < 1e-9 && box_at[i].x() > face - half - 2e-3;
        if (!resting) continue;
        const double hand = speed * std::min(t, duration);   // the hand target (the box's grab-time place)
        const double penetration = hand - box_at[i].x();     // hand past the box, along the wall normal
        const double pushed = -rows[n].force.x();            // the force on the hand points back (-x)
        // The hand's velocity fit (6 samples) is exact on a straight line, and zero six frames after
        // the stop; between, it straddles the corner.
        if (t < duration) {
            ++resting_moving;
            worst_moving = std::max(worst_moving, std::abs(pushed - (k * penetration + c * speed)));
        } else if (t >= duration + 6 * dt) {
            ++resting_still;
            worst_still = std::max(worst_still, std::abs(pushed - k * penetration));
            last_force = pushed;
            last_penetration = penetration;
        }
        EXPECT_LT(rows[n].force.tail<2>().norm(), 1e-6 * k) << "frame " << i;
    }
    std::printf("k = %.3f N/m, c = %.3f N s/m; resting frames: %d with the hand moving (|F - (k d + c v)| <= %.3g N), "
                "%d with it stopped (|F - k d| <= %.3g N); last: F = %.4f N, k d = %.4f N (d = %.6f m); "
                "deepest box face %.3g m\n",
                k, c, resting_moving, worst_moving, resting_still, worst_still, last_force, k * last_penetration,
                last_penetration, deepest);
    EXPECT_GE(resting_moving, 10);
    EXPECT_GE(resting_still, 30);
    // Tolerance 1e-4 N = k x 0.1 um: the resting box moves by less (measured 4e-7 N with the hand
    // moving, from the damper's view of sub-nanometre settling, and 3e-13 N after it stopped).
    EXPECT_LT(worst_moving, 1e-4);
    EXPECT_LT(worst_still, 1e-4);
    EXPECT_NEAR(last_penetration, 0.6 - (face - half), 1e-3);   // the box rests at the wall
    fs::remove_all(dir);
}

TEST(WallPush, HeldBallPressedDownTheStaircaseNeverSinksIntoAStep) {
    // ball_0 of the paper's staircase held by a hand moving down and forward at 0.3 m/s each way for
    // 1.5 s: pressed onto the top tread, dragged over its edge and pressed onto the next tread
    // (the target ends 0.15 m below where the ball can be). Native; no penetration recovery, and the
    // ball's centre never comes closer to a step than its radius minus the collision distance.
    test::registerBackendsOnce();
    PlayOptions o;
    o.scene_path = std::string(VROC_SOURCE_DIR) + "/scenes/staircase.json";
    o.backend = "native";
    o.device_spec = "analytic:motion=line,x=0.1,y=-0.3,z=1.25,vx=0.3,vz=-0.3,duration=1.5";
    o.frames = 150;
    o.eye_width = 32;
    o.eye_height = 24;
    double closest = 1e9, lowest_z = 1e9;
    o.on_frame = [&](int, const Backend& backend) {
        const Vec3 p = backend.bodyState(2).pose.position;
        closest = std::min(closest, test::staircaseDistance(p));
        lowest_z = std::min(lowest_z, p.z());
    };
    const PlayReport r = runPlay(o);
    ASSERT_EQ(r.grabs, 1);
    EXPECT_TRUE(r.throws.empty());
    std::printf("ball_0: closest centre to a step %.6f m (radius 0.05), lowest z %.4f m; warnings:", closest, lowest_z);
    for (const auto& [name, count] : r.warnings) std::printf(" %s=%llu", name.c_str(), static_cast<unsigned long long>(count));
    std::printf("\n");
    EXPECT_EQ(warningCount(r.warnings, "penetration_recovered"), 0u);
    EXPECT_GT(closest, 0.05 - 1e-3);
    EXPECT_LT(lowest_z, 0.96);   // it did get down onto the second tread (0.90 + 0.05)
}

}  // namespace
}  // namespace vroc::play
