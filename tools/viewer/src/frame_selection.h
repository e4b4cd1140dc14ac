// SPDX-License-Identifier: MIT
// Which recorded frames the page keeps: all of them, or every stride-th (and the last) when the run
// is longer than ViewerOptions::max_frames or the poses would pass ViewerOptions::max_pose_bytes.
#pragma once

#include <cstddef>
#include <vector>

#include "vroc/viewer/viewer_inputs.h"

namespace vroc::viewer {

struct FrameSelection {
    std::size_t stride = 1;           ///< [recorded frames] between kept frames
    std::vector<std::size_t> frames;  ///< recorded frame indices kept, increasing; the last included
};

/// `recorded` frames of `runs` runs with `moving_bodies` moving bodies each.
FrameSelection selectFrames(std::size_t recorded, std::size_t moving_bodies, std::size_t runs,
                            const ViewerOptions& options);

}  // namespace vroc::viewer
