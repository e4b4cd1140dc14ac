// SPDX-License-Identifier: MIT
// Small rotation helpers shared by the built-in plugins and the loader (rotation vectors in
// radians, quaternions as Eigen's; the ABI stores them x, y, z, w).
#pragma once

#include <cmath>
#include <cstdint>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "vroc/plugin/vroc_device_plugin.h"

namespace vroc::plugin_sdk {

/// exp map: the rotation by |rv| radians about rv.
inline Eigen::Quaterniond expRotation(const Eigen::Vector3d& rv) {
    const double angle = rv.norm();
    if (angle < 1e-12) return Eigen::Quaterniond(1.0, 0.5 * rv.x(), 0.5 * rv.y(), 0.5 * rv.z()).normalized();
    return Eigen::Quaterniond(Eigen::AngleAxisd(angle, rv / angle));
}

/// log map: the rotation vector of q, angle in [0, pi] (the shorter way round).
inline Eigen::Vector3d logRotation(Eigen::Quaterniond q) {
    if (q.w() < 0) q.coeffs() = -q.coeffs();
    const double s = q.vec().norm();
    if (s < 1e-12) return 2.0 * q.vec();
    return (2.0 * std::atan2(s, q.w()) / s) * q.vec();
}

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
