// SPDX-License-Identifier: MIT
// Host-side, checked copies of the ABI's pose and control structs.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "vroc/core/math.h"

namespace vroc::plugins {

/// A validated pose: every field flagged valid is finite and the quaternion is unit.
struct PoseSample {
    int64_t time_ns = 0;          ///< measurement time on the host clock [ns]
    uint32_t sensor = 0;
    uint32_t flags = 0;           ///< VROC_POSE_*
    uint64_t sequence = 0;
    Pose pose;                    ///< base <- sensor [m]
    Vec3 linear_velocity = Vec3::Zero();   ///< [m/s] base frame (if flagged)
    Vec3 angular_velocity = Vec3::Zero();  ///< [rad/s] base frame (if flagged)

    bool has(uint32_t flag) const { return (flags & flag) == flag; }
};

enum class SampleStatus {
    Ok,        ///< sample valid (code may be VROC_NO_NEW_DATA or VROC_EXTRAPOLATED)
    NoData,    ///< the device has nothing yet (VROC_ERROR_NO_DATA)
    Failed,    ///< the plugin returned another error; message holds last_error
    Rejected,  ///< the plugin returned success but the sample failed the host's checks
};

struct PoseResult {
    SampleStatus status = SampleStatus::Failed;
    int32_t code = 0;             ///< the plugin's return value
    PoseSample sample;            ///< meaningful only when ok()
    std::string message;          ///< why, when not ok()
    bool ok() const { return status == SampleStatus::Ok; }
};

struct ControlState {
    int64_t time_ns = 0;
    uint64_t buttons = 0;         ///< bit i = button i
    std::vector<double> axes;     ///< [-1, 1]
};

struct ControlResult {
    SampleStatus status = SampleStatus::Failed;
    int32_t code = 0;
    ControlState state;
    std::string message;
    bool ok() const { return status == SampleStatus::Ok; }
};

}  // namespace vroc::plugins
