// SPDX-License-Identifier: MIT
#include "force_csv_file.h"

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "vroc/core/csv.h"

namespace vroc::plugins::force_log {
ForceCsvFile::ForceCsvFile(std::string path) : path_(std::move(path)), partial_(path_ + ".partial") {
    // A log left by an earlier run must not pass for this run's: it disappears now and the new one
    // appears complete, by rename, at finish().
    if (std::remove(path_.c_str()) != 0 && errno != ENOENT)
        throw std::runtime_error("cannot replace " + path_ + ": " + std::strerror(errno));
    file_ = std::fopen(partial_.c_str(), "w");
    if (!file_) throw std::runtime_error("cannot create " + partial_ + ": " + std::strerror(errno));
    if (std::fprintf(file_, "%s\n", kForceCsvHeader) < 0 || std::fflush(file_) != 0) {
        const std::string why = std::strerror(errno);
        std::fclose(file_);
        file_ = nullptr;
        throw std::runtime_error("cannot write " + partial_ + ": " + why);
    }
}

ForceCsvFile::~ForceCsvFile() { finish(); }

std::string ForceCsvFile::append(const VrocForceCommand& c) {
    std::lock_guard lock(mutex_);
    if (!file_) return partial_ + " is already closed";
    std::string row;
    csv::appendInteger(row, c.time_ns);
    row += ',';
    csv::appendInteger(row, c.sensor);
    for (const double* v : {c.force, c.torque})
        for (int i = 0; i < 3; ++i) {
            row += ',';
            csv::appendNumber(row, v[i]);
        }
    row += '\n';
    // Flushed row by row so that a reader sees every force already handed over.
    if (std::fputs(row.c_str(), file_) < 0 || std::fflush(file_) != 0) {
        failed_ = true;
        return "cannot write " + partial_ + ": " + std::strerror(errno);
    }
    ++rows_;
    return {};
}

std::string ForceCsvFile::finish() {
    std::lock_guard lock(mutex_);
    if (!file_) return {};
    const bool write_error = std::ferror(file_) != 0 || failed_;
    const bool close_error = std::fclose(file_) != 0;
    file_ = nullptr;
    // An incomplete log keeps its .partial name: only a complete one may look complete.
    if (write_error || close_error) return "write error in " + partial_ + " (left as is)";
    if (std::rename(partial_.c_str(), path_.c_str()) != 0)
        return "cannot rename " + partial_ + " to " + path_ + ": " + std::strerror(errno);
    return {};
}

void ForceCsvFile::abandon() {
    std::lock_guard lock(mutex_);
    if (!file_) return;
    std::fclose(file_);
    file_ = nullptr;
    std::remove(partial_.c_str());
}

uint64_t ForceCsvFile::rows() const {
    std::lock_guard lock(mutex_);
    return rows_;
}

}  // namespace vroc::plugins::force_log
