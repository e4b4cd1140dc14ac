// SPDX-License-Identifier: MIT
#include "vroc/render/video_writer.h"

#include <sys/wait.h>

#include "vroc/core/errors.h"

namespace vroc::render {
namespace {
std::string shellQuote(const std::string& s) {
    std::string out = "'";
    for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}
}  // namespace

VideoWriter::VideoWriter(const std::string& path, int width, int height, double fps)
    : path_(path), width_(width), height_(height) {
    if (width % 2 != 0 || height % 2 != 0) throw RunError(path + ": MP4 (yuv420p) needs even width and height");
    const std::string command = "ffmpeg -loglevel error -y -f rawvideo -pix_fmt rgb24 -s " +
                                std::to_string(width) + "x" + std::to_string(height) + " -r " +
                                std::to_string(fps) + " -i - -c:v libx264 -pix_fmt yuv420p " + shellQuote(path);
    pipe_ = popen(command.c_str(), "w");
    if (!pipe_) throw RunError(path + ": cannot start ffmpeg");
}

VideoWriter::~VideoWriter() {
    if (pipe_) pclose(pipe_);
}

void VideoWriter::addFrame(const Image& image) {
    if (image.width != width_ || image.height != height_) throw RunError(path_ + ": frame size changed");
    if (!pipe_ || std::fwrite(image.rgb.data(), 1, image.rgb.size(), pipe_) != image.rgb.size())
        throw RunError(path_ + ": ffmpeg stopped accepting frames");
}

void VideoWriter::finish() {
    if (!pipe_) return;
    const int status = pclose(pipe_);
    pipe_ = nullptr;
    if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw RunError(path_ + ": ffmpeg failed (is ffmpeg with libx264 installed?)");
}

}  // namespace vroc::render
