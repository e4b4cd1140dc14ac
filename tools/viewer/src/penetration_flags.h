// SPDX-License-Identifier: MIT
// Which moving bodies are deeper than the scene's collision distance into another body, judged by
// the harness's neutral distance (harness::bodyDistance, the ruler the reports' penetration
// metric uses), at the kept frames.
#pragma once

#include <vector>

#include "vroc/core/scene.h"
#include "vroc/viewer/viewer_data.h"

namespace vroc::viewer {

/// [frame][moving body] for `run.poses` (moving bodies in scene order). Tracked bodies are never
/// flagged (they follow their device, not the physics).
std::vector<std::vector<bool>> penetrationFlags(const Scene& scene, const ViewerRun& run);

}  // namespace vroc::viewer
