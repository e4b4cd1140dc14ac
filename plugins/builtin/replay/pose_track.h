// SPDX-License-Identifier: MIT
// The samples of one sensor from a pose recording, in time order, with interpolation.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace vroc::plugins::replay {

struct TrackSample {
    int64_t time_ns;
    Eigen::Vector3d position;        ///< [m]
    Eigen::Quaterniond orientation;  ///< sensor -> base
    uint64_t buttons;
};

struct TrackPose {
    Eigen::Vector3d position;
    Eigen::Quaterniond orientation;
    Eigen::Vector3d linear_velocity;   ///< [m/s] between the bracketing samples
    Eigen::Vector3d angular_velocity;  ///< [rad/s] base frame, between the bracketing samples
    uint64_t buttons;                  ///< of the sample at or before the time
    uint64_t index;                    ///< of the sample at or before the time
    bool inside;                       ///< false when held at either end
};

/// Samples must be in non-decreasing time order (the loader checks).
class PoseTrack {
public:
    void add(const TrackSample& sample) { samples_.push_back(sample); }
    bool empty() const { return samples_.empty(); }
    int64_t firstTime() const { return samples_.front().time_ns; }
    int64_t lastTime() const { return samples_.back().time_ns; }
    /// Position linearly, orientation by slerp between the samples around t; held at the ends.
    TrackPose at(int64_t t) const;

private:
    std::vector<TrackSample> samples_;
};

}  // namespace vroc::plugins::replay
