// SPDX-License-Identifier: MIT
// The page's data as JSON text ("vroc-view/1", docs/viewer.md "Data format"): bodies with their
// geometry once each, and per run its poses, penetration flags and events as base64 of packed
// little-endian arrays.
//   poses:       Float32 [frame][moving body][6] = x y z qx qy qz; the quaternion [x, y, z, w] is
//                stored with w >= 0 (q and -q are one rotation) and w = sqrt(1 - x^2 - y^2 - z^2)
//                restored by the page: the one place the order is handled is quatFromPacked() in
//                page/viewer.js, which builds THREE.Quaternion(x, y, z, w) (three.js takes x, y, z, w too).
//   penetrating: bits, frame-major: bit (f * moving + k) set when body k penetrates at frame f.
//   events:      Float32 [event][6] = t body_a body_b px py pz (scene body indices).
// Each run also names its engine's tint ("#rrggbb", engine_tints.h).
#pragma once

#include <string>

#include "vroc/viewer/viewer_data.h"

namespace vroc::viewer {

/// The JSON text, safe inside an HTML <script> element (every '<' written as \u003c).
std::string pageDataJson(const ViewerData& data);

}  // namespace vroc::viewer
