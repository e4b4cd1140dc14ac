// SPDX-License-Identifier: MIT
// The force log written by the force-log plugin: one row per force command,
//   time_ns,sensor,fx,fy,fz,tx,ty,tz
// (host time [ns], sensor index, force [N] and torque [N m] in the base frame, doubles with 17
// significant digits so a round trip is exact, whatever the locale: vroc/core/csv.h). Rows go to
// PATH.partial and are flushed one by one; finish() closes it and renames it to PATH, so PATH
// exists only once the log is complete.
#pragma once

#include <cstdint>
#include <cstdio>
#include <mutex>
#include <string>

#include "vroc/plugin/vroc_device_plugin.h"

namespace vroc::plugins::force_log {

inline constexpr const char* kForceCsvHeader = "time_ns,sensor,fx,fy,fz,tx,ty,tz";

class ForceCsvFile {
public:
    /// Removes a stale PATH and creates PATH.partial with the header. Throws std::runtime_error.
    explicit ForceCsvFile(std::string path);
    /// finish() if not done yet; errors are swallowed here (call finish() to see them).
    ~ForceCsvFile();
    ForceCsvFile(const ForceCsvFile&) = delete;
    ForceCsvFile& operator=(const ForceCsvFile&) = delete;

    /// Appends and flushes one row. Thread-safe. Returns "" or the reason it failed.
    std::string append(const VrocForceCommand& command);
    /// Closes PATH.partial and renames it to PATH. Idempotent. Returns "" or the reason it failed.
    std::string finish();
    /// Closes and deletes PATH.partial (nothing was logged that anyone needs). Idempotent.
    void abandon();
    uint64_t rows() const;

private:
    std::string path_, partial_;
    mutable std::mutex mutex_;
    std::FILE* file_ = nullptr;
    uint64_t rows_ = 0;
    bool failed_ = false;
};

}  // namespace vroc::plugins::force_log
