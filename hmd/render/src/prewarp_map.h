// SPDX-License-Identifier: MIT
// Per-pixel lookup that pre-warps each eye's image for the lens: the screen pixel s shows the
// rendered pixel at distort(s), so after the lens the viewer sees the rendered image undistorted.
#pragma once

#include <vector>

#include "vroc/hmd/lens_distortion.h"
#include "vroc/render/image.h"

namespace vroc::render {

class PrewarpMap {
public:
    PrewarpMap() = default;
    PrewarpMap(const hmd::LensDistortion& lens, int eye_width, int eye_height);
    bool empty() const { return source_.empty(); }
    /// Applies the map to each eye half of a side-by-side image (black outside the rendered one).
    Image apply(const Image& image, int eye_width) const;

private:
    int eye_width_ = 0;
    int eye_height_ = 0;
    std::vector<int> source_;   // per eye pixel: source pixel index in the eye, or -1
};

}  // namespace vroc::render
