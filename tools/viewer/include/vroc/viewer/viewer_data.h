// SPDX-License-Identifier: MIT
// What the replay viewer page shows (docs/viewer.md): the scene's bodies with their geometry,
// once each, and per run (a backend, or an ensemble member on a backend) the poses of the moving
// bodies at the frames kept. Built from run directories by loadViewerData (viewer_inputs.h),
// written into the page by writeViewerPage (viewer_page.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "vroc/core/backend.h"
#include "vroc/core/scene.h"

namespace vroc::viewer {

/// One convex piece of a body's shape, in the body frame (a compound gives several).
struct ViewerPart {
    enum class Kind { Sphere, Box, Hull };
    Kind kind = Kind::Sphere;
    double radius = 0;                    ///< [m] Sphere
    Vec3 half_extents = Vec3::Zero();     ///< [m] Box
    std::vector<Vec3> vertices;           ///< [m] Hull, part frame
    std::vector<std::vector<int>> faces;  ///< Hull: vertex indices, counter-clockwise from outside
    Pose pose;                            ///< part frame -> body frame
};

struct ViewerBody {
    std::string name;
    BodyRole role = BodyRole::Virtual;  ///< real: wireframe; virtual: shaded; tracked: marked
    std::vector<ViewerPart> parts;
    Pose initial_pose;      ///< body frame -> world at t = 0 (real bodies stay there)
    int moving_index = -1;  ///< index into ViewerRun::poses' bodies; -1 for real bodies
};

/// One run's replay at the kept frames (ViewerData::times).
struct ViewerRun {
    std::string backend;  ///< registry name, e.g. "native"
    std::string label;    ///< shown in the page, e.g. "native" or "native #3"
    int member = -1;      ///< ensemble member index; -1 for a plain run
    bool median = true;   ///< false: an ensemble member drawn faintly around the median
    /// [frame][moving body] poses, moving bodies in ViewerBody::moving_index order.
    std::vector<std::vector<Pose>> poses;
    /// [frame][moving body]: deeper than the scene's collision distance into another body, by the
    /// harness's neutral distance (harness::closestDistance). Empty when not computed.
    std::vector<std::vector<bool>> penetrating;
    std::vector<CollisionEvent> events;  ///< as recorded (all of them; the page shows each briefly)
    /// "#rrggbb": its engine's tint (src/engine_tints.h), shared by an ensemble's members on one
    /// backend; its ghosts, legend entry and view label show it.
    std::string tint;
};

struct ViewerData {
    std::string title;  ///< e.g. "compare on 'staircase'"
    std::string scene_name;
    double collision_distance = 1e-3;  ///< [m] the scene's
    std::vector<ViewerBody> bodies;    ///< every scene body, scene order
    std::size_t moving_bodies = 0;     ///< bodies with moving_index >= 0
    std::vector<double> times;         ///< [s] kept frames
    std::size_t recorded_frames = 0;   ///< frames in the shortest run as recorded
    std::size_t stride = 1;            ///< every stride-th recorded frame is kept (and the last)
    std::vector<ViewerRun> runs;
    std::vector<std::string> notes;  ///< shown on the page (subsampling, members left out, ...)
};

}  // namespace vroc::viewer
