// SPDX-License-Identifier: MIT
#include "vroc/hmd/stereo_rig.h"

#include <cmath>
#include <numbers>

namespace vroc::hmd {

Vec3 StereoRig::eyeOffset(Eye eye) const {
    const double side = eye == Eye::Left ? -0.5 : 0.5;
    return {side * settings_.ipd, 0.0, settings_.eye_relief};
}

Pose StereoRig::eyePose(const Pose& head, Eye eye) const {
    // The eyes look the way the head frame does: only the origin moves.
    return {head.apply(eyeOffset(eye)), head.orientation};
}

Eigen::Matrix4d StereoRig::viewMatrix(const Pose& eye_pose) {
    const Pose inv = eye_pose.inverse();
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.topLeftCorner<3, 3>() = inv.orientation.toRotationMatrix();
    m.topRightCorner<3, 1>() = inv.position;
    return m;
}

Eigen::Matrix4d StereoRig::projectionMatrix() const {
    const double f = 1.0 / std::tan(0.5 * settings_.fov_y_deg * std::numbers::pi / 180.0);
    const double n = settings_.near_plane;
    const double fa = settings_.far_plane;
    Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
    p(0, 0) = f / settings_.aspect;
    p(1, 1) = f;
    p(2, 2) = (fa + n) / (n - fa);
    p(2, 3) = 2.0 * fa * n / (n - fa);
    p(3, 2) = -1.0;
    return p;
}

std::optional<PixelPoint> StereoRig::project(const Pose& eye_pose, const Vec3& world_point, int width,
                                             int height) const {
    const Vec3 local = eye_pose.applyInverse(world_point);
    if (local.z() >= -settings_.near_plane) return std::nullopt;   // behind or too close
    const Eigen::Vector4d clip = projectionMatrix() * Eigen::Vector4d(local.x(), local.y(), local.z(), 1.0);
    const double nx = clip.x() / clip.w();
    const double ny = clip.y() / clip.w();
    if (std::abs(nx) > 1.0 || std::abs(ny) > 1.0) return std::nullopt;
    return PixelPoint{0.5 * (nx + 1.0) * width, 0.5 * (1.0 - ny) * height, -local.z()};
}

Pose lookAt(const Vec3& eye, const Vec3& target, const Vec3& up) {
    const Vec3 forward = (target - eye).normalized();
    const Vec3 right = forward.cross(up).normalized();
    const Vec3 true_up = right.cross(forward);
    Mat3 r;
    r.col(0) = right;
    r.col(1) = true_up;
    r.col(2) = -forward;
    return {eye, Quat(r).normalized()};
}

}  // namespace vroc::hmd
