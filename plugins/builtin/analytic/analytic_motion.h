// SPDX-License-Identifier: MIT
// Scripted motions whose pose and velocities are closed-form functions of time (ground truth for
// tests, after vrpn_Tracker_Spin and Monado's simulated HMD). Base frame: z up, metres, seconds.
#pragma once

#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace vroc::plugins::analytic {

struct MotionState {
    Eigen::Vector3d position;          ///< [m] base frame
    Eigen::Quaterniond orientation;    ///< sensor -> base
    Eigen::Vector3d linear_velocity;   ///< [m/s] base frame
    Eigen::Vector3d angular_velocity;  ///< [rad/s] base frame
    bool button = false;               ///< button 0 (held during the throw's wind-up, from press_at in a line)
};

enum class MotionKind { Static, Circle, FigureEight, Throw, HeadTurn, Spin, Line };

struct MotionParams {
    MotionKind kind = MotionKind::Circle;
    Eigen::Vector3d center{0.0, 0.0, 1.2};  ///< [m] circle centre, shoulder pivot, head position
    double radius = 0.3;                    ///< [m] circle/figure-eight size, arm length for throw
    double period = 2.0;                    ///< [s] one cycle (circle, figure-eight, throw)
    double speed = 3.4906585039886591;      ///< head-turn peak / spin rate [rad/s] (200 deg/s); throw release speed [m/s]
    double amplitude = 0.5235987755982988;  ///< [rad] head-turn yaw amplitude (30 deg)
    // Line: from `center` at t = 0 with constant `velocity` until `duration`, then at rest there;
    // at rest at `center` before t = 0. Orientation fixed. Button 0 held for t >= press_at.
    Eigen::Vector3d velocity{0.0, 0.0, 0.0};                    ///< [m/s] base frame
    Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< sensor -> base, fixed
    double press_at = 0.0;                                      ///< [s] button 0 pressed from then on
    double duration = 0.0;                                      ///< [s] of motion; 0 = unbounded
};

/// "circle" -> MotionKind::Circle etc.; false if unknown.
bool parseMotionKind(const std::string& text, MotionKind& kind);

/// The motion at time t [s] (any t; periodic motions repeat).
MotionState evaluateMotion(const MotionParams& params, double t);

/// Throw: wind-up from the arm pointing back horizontally to the release angle (0.5 rad above the
/// lowest point, moving forward and up) under constant angular acceleration; button 0 held until
/// release; then a constant deceleration to rest. Release time [s] within a cycle:
double throwReleaseTime(const MotionParams& params);

}  // namespace vroc::plugins::analytic
