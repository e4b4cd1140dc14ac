// SPDX-License-Identifier: MIT
// An 8-bit RGB image, rows top to bottom (as PNG stores them), and its writers.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace vroc::render {

struct Image {
    int width = 0;                       ///< [px]
    int height = 0;                      ///< [px]
    std::vector<std::uint8_t> rgb;       ///< width * height * 3 bytes, row 0 = top

    std::array<std::uint8_t, 3> at(int x, int y) const {
        const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3;
        return {rgb[i], rgb[i + 1], rgb[i + 2]};
    }
};

/// Writes an 8-bit RGB PNG (libpng, fast compression). Throws RunError naming the file on failure.
void writePng(const std::string& path, const Image& image);
/// Reads an 8-bit RGB PNG written by writePng (for tests and tools). Throws RunError on failure.
Image readPng(const std::string& path);

}  // namespace vroc::render
