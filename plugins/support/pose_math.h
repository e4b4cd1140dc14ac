// SPDX-License-Identifier: MIT
// Pose helpers shared by the built-in plugins and the loader (quaternions as Eigen's; the ABI
// stores them x, y, z, w). Rotation vectors: vroc/core/rotation_vector.h.
#pragma once

#include <cmath>
#include <cstdint>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "vroc/core/rotation_vector.h"   // header-only: the exp and log maps of SO(3)
#include "vroc/plugin/vroc_device_plugin.h"

namespace vroc::plugin_sdk {

inline Eigen::Vector3d positionOf(const VrocPoseSample& s) {
    return {s.position[0], s.position[1], s.position[2]};
}
inline Eigen::Quaterniond orientationOf(const VrocPoseSample& s) {
    return Eigen::Quaterniond(s.orientation[3], s.orientation[0], s.orientation[1], s.orientation[2]);
}

/// Writes pose, time and flags; velocities only when given (flags set accordingly).
inline void writePose(VrocPoseSample& out, int64_t time_ns, uint32_t sensor, const Eigen::Vector3d& p,
                      const Eigen::Quaterniond& q, uint32_t flags, const Eigen::Vector3d* v = nullptr,
                      const Eigen::Vector3d* w = nullptr) {
    out.time_ns = time_ns;
    out.sensor = sensor;
    out.flags = flags;
    for (int i = 0; i < 3; ++i) out.position[i] = p[i];
    const Eigen::Quaterniond n = q.normalized();
    out.orientation[0] = n.x();
    out.orientation[1] = n.y();
    out.orientation[2] = n.z();
    out.orientation[3] = n.w();
    for (int i = 0; i < 3; ++i) out.linear_velocity[i] = v ? (*v)[i] : 0.0;
    for (int i = 0; i < 3; ++i) out.angular_velocity[i] = w ? (*w)[i] : 0.0;
    if (v) out.flags |= VROC_POSE_LINEAR_VELOCITY_VALID;
    if (w) out.flags |= VROC_POSE_ANGULAR_VELOCITY_VALID;
}

constexpr uint32_t kPoseValidTracked = VROC_POSE_ORIENTATION_VALID | VROC_POSE_POSITION_VALID |
                                       VROC_POSE_ORIENTATION_TRACKED | VROC_POSE_POSITION_TRACKED;
constexpr uint32_t kPoseValid = VROC_POSE_ORIENTATION_VALID | VROC_POSE_POSITION_VALID;

inline double secondsOf(int64_t ns) { return static_cast<double>(ns) * 1e-9; }
inline int64_t nsOf(double seconds) { return static_cast<int64_t>(std::llround(seconds * 1e9)); }

}  // namespace vroc::plugin_sdk
