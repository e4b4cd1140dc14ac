// SPDX-License-Identifier: MIT
// The default head motion of `vroc play` (no --head): a viewer standing in front of the scene,
// looking at its middle and shaking the head gently (yaw 15 deg at 0.4 Hz, pitch 4 deg at
// 0.25 Hz; peak yaw rate 38 deg/s), and the mounting of a head-tracker plugin's sensor frame.
#pragma once

#include "vroc/core/math.h"
#include "vroc/core/scene.h"

namespace vroc::play {

struct ScriptedHead {
    Pose base;                     ///< head frame -> world at rest
    double yaw_amplitude = 15.0 * 3.14159265358979323846 / 180.0;    ///< [rad]
    double yaw_frequency = 0.4;    ///< [Hz]
    double pitch_amplitude = 4.0 * 3.14159265358979323846 / 180.0;   ///< [rad]
    double pitch_frequency = 0.25; ///< [Hz]

    /// Placed from the scene: looks at the middle of the bodies that are not huge (floors are
    /// left out), from 2.7 m in front (-y) and 0.5 m above.
    static ScriptedHead forScene(const Scene& scene);
    Pose at(double t) const;       ///< head frame -> world at time t [s]
};

/// Head frame from a head-tracker sensor pose: the sensor frame is z up and looks along +y
/// (so an analytic "head-turn" at yaw 0 faces +y); the head frame looks down -z with y up.
Pose headFromSensor(const Pose& sensor);

}  // namespace vroc::play
