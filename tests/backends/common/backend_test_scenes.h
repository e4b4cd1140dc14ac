// SPDX-License-Identifier: MIT
// Scenarios for the reference backends' tests (bullet, ode, mujoco): strikes, drops, lifts and
// timed runs, built with the shared scene builders (tests/support/test_scene_builder.h); each suite
// adds its own make<Backend>().
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "test_scene_builder.h"
#include "vroc/core/backend.h"
#include "vroc/core/scene.h"

namespace vroc::test {

/// A plate strikes a ball: no gravity, ball r = 0.1 m, 1 kg, at rest at the origin; a tracked plate
/// (box, half extents 0.05 x 0.5 x 0.5 m) on the -x side, its +x face `gap` [m] from the ball,
/// moving at +x `speed` [m/s]; one material, restitution e, friction 0. The closed form: the ball
/// leaves at (1 + e) speed along +x and the plate keeps p(t) = p0 + (speed, 0, 0) t.
struct TrackedStrike {
    Scene scene;
    int ball = -1, plate = -1;
    Vec3 plate_start = Vec3::Zero();   ///< [m] plate origin at t = 0
};
TrackedStrike trackedStrike(double e, double speed, double gap);
/// The same strike seen from the plate: the plate is a real (static) body and the ball flies at
/// -x `speed` towards it. By Galilean invariance the ball's velocity after it, plus `speed`, is the
/// tracked strike's.
TrackedStrike staticStrike(double e, double speed, double gap);
/// What a strike run measured.
struct StrikeRun {
    Vec3 ball_velocity = Vec3::Zero();         ///< [m/s] after the last frame
    Vec3 ball_angular_velocity = Vec3::Zero(); ///< [rad/s] after the last frame
    double contact_gap = 0.0;    ///< [m] face-to-ball gap at the start of the frame in which the ball first moved
    double plate_error = 0.0;    ///< [m] largest |plate origin - (p0 + v t)| over the frames
    double plate_velocity_error = 0.0;   ///< [m/s] largest |plate velocity - v| over the frames
    int events = 0;              ///< collision events reported
};
/// Steps `backend` (made for `strike.scene`) `frames` frames of `dt` [s]; the plate's prescribed
/// velocity is (plate_speed, 0, 0) (0 for staticStrike).
StrikeRun runStrike(Backend& backend, const TrackedStrike& strike, double plate_speed, double dt, int frames);

/// `key=value` setting overrides for a backend.
using Overrides = std::vector<std::pair<std::string, std::string>>;

/// Creates the registered backend `name` (registered by the caller) with overrides.
std::unique_ptr<Backend> makeRegistered(const std::string& name, const Scene& scene, const Overrides& overrides = {});

/// The top-level shipped scenes, scenes/*.json, sorted.
std::vector<std::filesystem::path> shippedSceneFiles();

/// 64 hull cubes (0.1 m) in a 4 x 4 x 4 lattice, each turned a little more, falling on the floor.
Scene fallingHullCubes();

/// Wall time [us] of every stepFrame over `frames` frames, and the events taken meanwhile.
struct TimedRun {
    std::vector<double> frame_us;   ///< in step order
    std::size_t events = 0;
    double totalSeconds() const;
    /// The q-quantile (0..1) of the frame times (nearest rank below).
    double quantileUs(double q) const;
};
TimedRun timedRun(Backend& backend, const Scene& scene, int frames);

/// Makes a backend for a scene with overrides (make<Backend>()).
using BackendFactory = std::function<std::unique_ptr<Backend>(const Scene&, const Overrides&)>;

/// A ball drop: ball r = 0.1 m, m = 1 kg, bottom 1 m above the floor (top face z = 0), both
/// materials restitution e, up to 20 s or `count` apexes; the events counted meanwhile.
struct DropResult {
    std::vector<double> apexes;   ///< [m] bottom heights at the apexes
    int events = 0;
};
/// How an apex is read from frames: the larger of the two frame heights around the turn (as
/// trajectory.csv would show it), or the last rising frame's height plus vz^2 / (2 g) (the
/// ballistic arc's exact top; frame sampling loses up to 0.3 mm).
enum class ApexReading { FrameMax, Ballistic };
DropResult ballDrop(const BackendFactory& make, double e, const Overrides& overrides, int count,
                    ApexReading reading = ApexReading::FrameMax);
/// One Markdown row: | e | label | events | apex n (deviation from e^(2n) h) ... | for 5 apexes.
void printApexRow(double e, const char* label, const DropResult& r);

/// A lift: gravity -9.81 z; a tracked platform (box, half extents 0.5 x 0.5 x 0.05 m, top face at
/// z = 0) rising at `speed` [m/s]; a 0.2 m box of 2 kg resting on it (released 0.5 mm above);
/// one material, restitution 0.2, friction 0.6. The box should ride on the platform at `speed`.
/// Returns, after each of `frames` frames of `dt` [s], the gap [m] between the box's bottom face and
/// the platform's top face and the box's vertical velocity [m/s].
struct LiftSample {
    double gap = 0.0;
    double box_vz = 0.0;
};
std::vector<LiftSample> trackedLift(const BackendFactory& make, double speed, double dt, int frames,
                                    const Overrides& overrides = {});

}  // namespace vroc::test
