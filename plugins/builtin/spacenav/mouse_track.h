// SPDX-License-Identifier: MIT
// The pose of a live 3D mouse: its deflections change only at events (host time of arrival), so
// between events the AnalogFly integration (analog_fly.h) is exact. The track keeps the state at
// each event (the newest `max_history`), so the pose at any time after the oldest kept event is
// exact, and the pose at a time after the newest event integrates the held deflection up to it.
// Not thread-safe: the owner locks.
#pragma once

#include <cstdint>
#include <deque>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "analog_fly.h"

namespace vroc::plugins::spacenav {

using plugin_sdk::AnalogFly;
using plugin_sdk::MouseAxes;

struct MouseSample {
    int64_t event_time_ns = 0;         ///< [ns] host time of the newest event at or before the asked time
    uint64_t sequence = 0;             ///< events applied up to the asked time
    Eigen::Vector3d position;          ///< [m] base frame
    Eigen::Quaterniond orientation;    ///< sensor -> base
    Eigen::Vector3d linear_velocity;   ///< [m/s] base frame
    Eigen::Vector3d angular_velocity;  ///< [rad/s] base frame
    MouseAxes axes{};                  ///< held deflections, VROC axes
    uint64_t buttons = 0;              ///< bit i = button i
};

class MouseTrack {
public:
    /// At rest at `start` (identity orientation) from host time t0 on.
    MouseTrack(const AnalogFly& fly, const Eigen::Vector3d& start, int64_t t0, size_t max_history = 4096);

    /// An event at host time t (clamped to the newest event's time, so the track never runs back).
    void setAxes(int64_t t, const MouseAxes& axes);
    void setButton(int64_t t, int button, bool pressed);  ///< button in [0, 63]
    /// Deflections zero and every button up at host time t (the device went away).
    void release(int64_t t) { push(t, MouseAxes{}, 0); }
    /// The state at host time t. Before t0 (or before the oldest kept event) the state of that event.
    MouseSample at(int64_t t) const;
    int64_t newestEventTime() const { return segments_.back().t0; }

private:
    struct Segment {
        int64_t t0;
        Eigen::Vector3d position;
        Eigen::Quaterniond orientation;
        MouseAxes axes;
        uint64_t buttons;
        uint64_t sequence;
    };
    void push(int64_t t, const MouseAxes& axes, uint64_t buttons);

    AnalogFly fly_;
    size_t max_history_;
    std::deque<Segment> segments_;  // by time; never empty
};

}  // namespace vroc::plugins::spacenav
