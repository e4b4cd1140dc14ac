// SPDX-License-Identifier: MIT
#include "vroc/render/video_writer.h"

#include "vroc/core/errors.h"

namespace vroc::render {

namespace {

std::vector<std::string> ffmpegArguments(const std::string& path, int width, int height, double fps) {
    return {"ffmpeg", "-loglevel", "error", "-y", "-f", "rawvideo", "-pix_fmt", "rgb24",
            "-s", std::to_string(width) + "x" + std::to_string(height), "-r", std::to_string(fps),
            "-i", "-", "-c:v", "libx264", "-pix_fmt", "yuv420p", path};
}

}  // namespace

VideoWriter::VideoWriter(const std::string& path, int width, int height, double fps)
    : path_(path), width_(width), height_(height) {
    if (width % 2 != 0 || height % 2 != 0) throw RunError(path + ": MP4 (yuv420p) needs even width and height");
    SpawnOptions options;
    options.stdin_pipe = true;
    try {
        ffmpeg_.emplace(ffmpegArguments(path, width, height, fps), options);
    } catch (const RunError& e) {
        throw RunError(path + ": " + e.what() + " (is ffmpeg installed?)");
    }
}

VideoWriter::~VideoWriter() = default;   // Subprocess closes the pipe and waits

void VideoWriter::addFrame(const Image& image) {
    if (image.width != width_ || image.height != height_) throw RunError(path_ + ": frame size changed");
    if (!ffmpeg_ || !ffmpeg_->write(image.rgb.data(), image.rgb.size()))
        throw RunError(path_ + ": ffmpeg stopped accepting frames");
}

void VideoWriter::finish() {
    if (!ffmpeg_) return;
    const int status = ffmpeg_->wait();
    ffmpeg_.reset();
    if (status != 0) throw RunError(path_ + ": ffmpeg failed (is ffmpeg with libx264 installed?)");
}

}  // namespace vroc::render
