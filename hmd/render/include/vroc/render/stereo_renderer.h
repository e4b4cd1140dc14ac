// SPDX-License-Identifier: MIT
// The OSMesa offscreen renderer of the merged view, both eyes side by side (left eye on the
// left). For each eye: the real model goes into the depth buffer only (colour writes off), then
// the virtual objects are drawn shaded (so real objects in front hide them), then the real model
// as a wireframe on top, as the 1995 system showed it. Black is "see-through". With lens
// distortion set, the image is pre-warped so the optics show it undistorted.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "vroc/core/math.h"
#include "vroc/core/scene.h"
#include "vroc/hmd/stereo_rig.h"
#include "vroc/render/image.h"

namespace vroc::render {

struct RenderSettings {
    int eye_width = 640;                               ///< [px] per eye
    int eye_height = 480;                              ///< [px]
    std::array<float, 3> wireframe_color{0.f, 1.f, 0.f};   ///< real model edges (RGB in [0, 1])
    float line_width = 1.0f;                           ///< [px]
    int sphere_slices = 24;                            ///< tessellation of spheres
    int sphere_stacks = 16;
};

/// Colour of virtual body number `virtual_index` (in scene order): a fixed palette.
std::array<float, 3> virtualColor(int virtual_index);

class StereoRenderer {
public:
    /// Creates the OSMesa context and the meshes of every body of `scene` (kept by value; the
    /// renderer does not reference the scene afterwards). Throws RunError if OSMesa fails.
    StereoRenderer(const Scene& scene, const hmd::StereoRig& rig, const RenderSettings& settings);
    ~StereoRenderer();
    StereoRenderer(const StereoRenderer&) = delete;
    StereoRenderer& operator=(const StereoRenderer&) = delete;

    /// Draws both eyes. `eye_poses`: eye frame -> world (left, right); `body_poses`: body frame ->
    /// world for every scene body (real bodies included), in scene order.
    void render(const std::array<Pose, 2>& eye_poses, const std::vector<Pose>& body_poses);
    /// The last frame, rows top-down, pre-warped if the rig has lens distortion.
    Image image() const;
    int width() const { return 2 * settings_.eye_width; }
    int height() const { return settings_.eye_height; }
    std::string glRenderer() const;   ///< e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    RenderSettings settings_;
};

}  // namespace vroc::render
