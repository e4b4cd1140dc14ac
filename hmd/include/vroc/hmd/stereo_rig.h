// SPDX-License-Identifier: MIT
// Stereo geometry of the display. Frames follow OpenGL's camera convention: the head frame (the
// tracked lens plane centre) and each eye frame have x right, y up and look down -z. Each eye's
// centre of projection sits ipd/2 to its side and eye_relief behind (+z) the head frame origin.
#pragma once

#include <optional>

#include <Eigen/Core>

#include "vroc/core/math.h"
#include "vroc/hmd/hmd_settings.h"

namespace vroc::hmd {

enum class Eye { Left = 0, Right = 1 };

/// A pixel position: x to the right from the left image edge, y down from the top edge, in pixels
/// (pixel (i, j) covers [i, i+1) x [j, j+1)), plus the eye-frame depth [m] (> 0 in front).
struct PixelPoint {
    double x = 0.0;
    double y = 0.0;
    double depth = 0.0;
};

class StereoRig {
public:
    explicit StereoRig(const HmdSettings& settings) : settings_(settings) {}

    const HmdSettings& settings() const { return settings_; }
    /// [m] eye centre in the head frame.
    Vec3 eyeOffset(Eye eye) const;
    /// Eye frame -> world, for the head frame -> world pose `head`.
    Pose eyePose(const Pose& head, Eye eye) const;
    /// World -> eye-frame 4x4 (OpenGL column-vector convention).
    static Eigen::Matrix4d viewMatrix(const Pose& eye_pose);
    /// OpenGL perspective projection (symmetric frustum, vertical fov, aspect, near, far).
    Eigen::Matrix4d projectionMatrix() const;
    /// Where a world point lands in a width x height eye image; nullopt behind the eye or outside.
    std::optional<PixelPoint> project(const Pose& eye_pose, const Vec3& world_point, int width,
                                      int height) const;

private:
    HmdSettings settings_;
};

/// Head frame -> world pose of a viewer at `eye` looking at `target` with world +z up.
Pose lookAt(const Vec3& eye, const Vec3& target, const Vec3& up = Vec3::UnitZ());

}  // namespace vroc::hmd
