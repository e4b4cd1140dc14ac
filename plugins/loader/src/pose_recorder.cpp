// SPDX-License-Identifier: MIT
#include "vroc/plugin/pose_recorder.h"

#include <cerrno>
#include <cstring>

#include "pose_csv.h"
#include "vroc/core/errors.h"

namespace vroc::plugins {

PoseRecorder::PoseRecorder(const std::string& path) : path_(path), file_(std::fopen(path.c_str(), "w")) {
    if (!file_) throw RunError(path + ": cannot create pose recording: " + std::strerror(errno));
    std::fprintf(file_, "%s\n", plugin_sdk::kPoseCsvHeader);
}

PoseRecorder::~PoseRecorder() {
    if (file_) std::fclose(file_);
}

void PoseRecorder::add(const PoseSample& sample, uint64_t buttons) {
    if (!file_) throw RunError(path_ + ": pose recording already closed");
    plugin_sdk::PoseCsvRow row;
    row.time_ns = sample.time_ns;
    row.sensor = sample.sensor;
    for (int i = 0; i < 3; ++i) row.position[i] = sample.pose.position[i];
    const Quat& q = sample.pose.orientation;
    row.orientation = {q.x(), q.y(), q.z(), q.w()};
    row.buttons = buttons;
    std::fprintf(file_, "%s\n", plugin_sdk::formatPoseCsvRow(row).c_str());
    ++rows_;
}

void PoseRecorder::close() {
    if (!file_) return;
    const bool failed = std::ferror(file_) != 0;
    const bool close_failed = std::fclose(file_) != 0;
    file_ = nullptr;
    if (failed || close_failed) throw RunError(path_ + ": write error in pose recording");
}

}  // namespace vroc::plugins
