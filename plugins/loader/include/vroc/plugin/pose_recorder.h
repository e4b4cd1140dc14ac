// SPDX-License-Identifier: MIT
// Writes pose samples to the CSV the replay plugin reads (format in plugins/support/pose_csv.h):
//   time_ns,sensor,x,y,z,qx,qy,qz,qw,buttons
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

#include "vroc/plugin/pose_sample.h"

namespace vroc::plugins {

class PoseRecorder {
public:
    /// Creates (truncates) `path` and writes the header. Throws RunError if it cannot.
    explicit PoseRecorder(const std::string& path);
    ~PoseRecorder();
    PoseRecorder(const PoseRecorder&) = delete;
    PoseRecorder& operator=(const PoseRecorder&) = delete;

    /// Appends one row (17 significant digits: exact round trip).
    void add(const PoseSample& sample, uint64_t buttons = 0);
    /// Flushes and closes; throws RunError on a write error. Called by the destructor otherwise.
    void close();
    uint64_t rows() const { return rows_; }

private:
    std::string path_;
    std::FILE* file_ = nullptr;
    uint64_t rows_ = 0;
};

}  // namespace vroc::plugins
