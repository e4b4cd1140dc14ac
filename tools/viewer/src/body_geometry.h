// SPDX-License-Identifier: MIT
// The scene's bodies as the viewer draws them: each shape split into convex parts, once per body.
#pragma once

#include <vector>

#include "vroc/core/scene.h"
#include "vroc/viewer/viewer_data.h"

namespace vroc::viewer {

/// Every scene body in scene order; moving bodies (virtual, tracked) numbered in scene order, as
/// trajectory.csv lists them.
std::vector<ViewerBody> viewerBodies(const Scene& scene);

}  // namespace vroc::viewer
