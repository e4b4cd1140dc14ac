// SPDX-License-Identifier: MIT
// MP4 output: raw RGB frames piped into an ffmpeg subprocess (libx264, yuv420p).
#pragma once

#include <optional>
#include <string>

#include "vroc/core/subprocess.h"
#include "vroc/render/image.h"

namespace vroc::render {

class VideoWriter {
public:
    /// Starts `ffmpeg` writing `path` at `fps` frames per second for width x height frames
    /// (both even, as yuv420p needs). Throws RunError if ffmpeg cannot start (not installed).
    VideoWriter(const std::string& path, int width, int height, double fps);
    ~VideoWriter();   ///< finishes if finish() was not called (errors ignored)
    VideoWriter(const VideoWriter&) = delete;
    VideoWriter& operator=(const VideoWriter&) = delete;

    void addFrame(const Image& image);   ///< throws RunError on a size mismatch or broken pipe
    /// Closes ffmpeg's input and waits for it; throws RunError if it failed.
    void finish();

private:
    std::string path_;
    int width_;
    int height_;
    std::optional<Subprocess> ffmpeg_;   ///< reads raw frames on its stdin; empty once finished
};

}  // namespace vroc::render
