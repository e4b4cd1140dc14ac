// SPDX-License-Identifier: MIT
#include "frame_selection.h"

#include <algorithm>

namespace vroc::viewer {

FrameSelection selectFrames(std::size_t recorded, std::size_t moving_bodies, std::size_t runs,
                            const ViewerOptions& options) {
    FrameSelection out;
    if (recorded == 0) return out;
    constexpr std::size_t kBytesPerPose = 6 * sizeof(float);  // page_payload.cpp: x y z qx qy qz (w >= 0)
    const std::size_t per_frame = std::max<std::size_t>(1, moving_bodies * runs * kBytesPerPose);
    const std::size_t cap = std::max<std::size_t>(2, std::min(options.max_frames, options.max_pose_bytes / per_frame));
    if (recorded > cap) out.stride = (recorded - 1 + cap - 2) / (cap - 1);
    for (std::size_t f = 0; f < recorded; f += out.stride) out.frames.push_back(f);
    if (out.frames.back() != recorded - 1) out.frames.push_back(recorded - 1);
    return out;
}

}  // namespace vroc::viewer
