// SPDX-License-Identifier: MIT
#include "prewarp_map.h"

#include <cmath>

namespace vroc::render {

PrewarpMap::PrewarpMap(const hmd::LensDistortion& lens, int eye_width, int eye_height)
    : eye_width_(eye_width), eye_height_(eye_height), source_(static_cast<std::size_t>(eye_width) * eye_height, -1) {
    // Coordinates normalised by the half height (lens_distortion.h), pixel centres.
    const double half_h = 0.5 * eye_height, half_w = 0.5 * eye_width;
    for (int y = 0; y < eye_height; ++y) {
        for (int x = 0; x < eye_width; ++x) {
            const hmd::Vec2 s((x + 0.5 - half_w) / half_h, (half_h - (y + 0.5)) / half_h);
            const hmd::Vec2 a = lens.distort(s);
            const int sx = static_cast<int>(std::floor(a.x() * half_h + half_w));
            const int sy = static_cast<int>(std::floor(half_h - a.y() * half_h));
            if (sx >= 0 && sx < eye_width && sy >= 0 && sy < eye_height)
                source_[static_cast<std::size_t>(y) * eye_width + x] = sy * eye_width + sx;
        }
    }
}

Image PrewarpMap::apply(const Image& image, int eye_width) const {
    Image out = image;
    for (int e = 0; e * eye_width < image.width; ++e) {
        for (int y = 0; y < eye_height_; ++y) {
            for (int x = 0; x < eye_width_; ++x) {
                const int s = source_[static_cast<std::size_t>(y) * eye_width_ + x];
                std::uint8_t* dst = &out.rgb[(static_cast<std::size_t>(y) * image.width + e * eye_width + x) * 3];
                if (s < 0) {
                    dst[0] = dst[1] = dst[2] = 0;
                    continue;
                }
                const int sx = s % eye_width_, sy = s / eye_width_;
                const std::uint8_t* src = &image.rgb[(static_cast<std::size_t>(sy) * image.width + e * eye_width + sx) * 3];
                dst[0] = src[0];
                dst[1] = src[1];
                dst[2] = src[2];
            }
        }
    }
    return out;
}

}  // namespace vroc::render
