// SPDX-License-Identifier: MIT
// Six-axis deflections integrated into a sensor pose, like VRPN's vrpn_Tracker_AnalogFly: the
// translation axes (0-2) move the sensor in the base frame at deflection x max_speed [m/s]; the
// rotation axes (3-5) turn it about its own axes at deflection x max_rate [rad/s]. Deflections held
// constant over an interval give a closed form, so a session of piecewise-constant deflections
// (a script, or a real 3D mouse's events) integrates exactly. Shared by spacemouse-sim and spacenav.
#pragma once

#include <array>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "pose_math.h"

namespace vroc::plugin_sdk {

using MouseAxes = std::array<double, 6>;  ///< tx, ty, tz, rx, ry, rz deflections in [-1, 1], base/sensor axes

struct AnalogFly {
    double max_speed = 0.5;  ///< [m/s] at full deflection
    double max_rate = 1.5707963267948966;  ///< [rad/s] at full deflection (90 deg/s)

    Eigen::Vector3d linearVelocity(const MouseAxes& a) const { return max_speed * Eigen::Vector3d(a[0], a[1], a[2]); }
    /// Angular velocity in the sensor frame (constant while the deflection is held).
    Eigen::Vector3d bodyRate(const MouseAxes& a) const { return max_rate * Eigen::Vector3d(a[3], a[4], a[5]); }

    /// The pose after holding `a` for dt seconds from (position, orientation).
    void advance(Eigen::Vector3d& position, Eigen::Quaterniond& orientation, const MouseAxes& a, double dt) const {
        position += linearVelocity(a) * dt;
        orientation = (orientation * quatFromRotationVector(bodyRate(a) * dt)).normalized();
    }
    /// The angular velocity in the base frame at `orientation` (the body rate turns with the sensor).
    Eigen::Vector3d angularVelocity(const Eigen::Quaterniond& orientation, const MouseAxes& a) const {
        return orientation * bodyRate(a);
    }
};

}  // namespace vroc::plugin_sdk
