// SPDX-License-Identifier: MIT
// A scripted 3D-mouse session: segments of constant six-axis deflection and buttons, integrated
// into a pose like VRPN's AnalogFly. Translation axes move the sensor in the base frame
// (deflection x max_speed); rotation axes turn it about its own axes (deflection x max_rate).
// Within a segment both are constant, so the pose has a closed form at any time.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace vroc::plugins::spacemouse_sim {

struct MouseSegment {
    double duration = 0;            ///< [s] > 0
    std::array<double, 6> axes{};   ///< tx, ty, tz, rx, ry, rz deflections in [-1, 1]
    uint64_t buttons = 0;
};

struct MouseState {
    Eigen::Vector3d position;
    Eigen::Quaterniond orientation;
    Eigen::Vector3d linear_velocity;   ///< [m/s] base frame
    Eigen::Vector3d angular_velocity;  ///< [rad/s] base frame
    std::array<double, 6> axes{};
    uint64_t buttons = 0;
};

/// Parses "DURATION:tx:ty:tz:rx:ry:rz[:BUTTONS]" segments separated by '/' or newlines ('#'
/// starts a comment). Throws OptionError naming the segment.
std::vector<MouseSegment> parseMouseScript(const std::string& text);

class MouseScript {
public:
    MouseScript(std::vector<MouseSegment> segments, const Eigen::Vector3d& start, double max_speed, double max_rate);
    /// The state at t [s] after the script start; before 0 and after the end: at rest.
    MouseState at(double t) const;

private:
    MouseState advance(const MouseState& from, const MouseSegment& segment, double dt) const;

    std::vector<MouseSegment> segments_;
    std::vector<MouseState> starts_;  // state at each segment's start, plus the end
    std::vector<double> start_times_;
    double max_speed_, max_rate_;
};

}  // namespace vroc::plugins::spacemouse_sim
