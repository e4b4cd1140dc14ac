// SPDX-License-Identifier: MIT
// Output that never looks complete before it is: every file is written as "<name>.tmp" and renamed
// into place when finished, and run.json (the marker of a complete run) is renamed last.
// An interrupted or failed run therefore leaves at most *.tmp files and no run.json.
#pragma once

#include <cstdio>
#include <filesystem>
#include <string_view>

#include "vroc/core/recording/text_sink.h"

namespace vroc::recording {

/// A file written under "<final>.tmp" and renamed to its final name by commit(). If destroyed
/// before commit() (exception, early return) the temporary file is removed.
class AtomicFile final : public TextSink {
public:
    /// Creates "<final_path>.tmp". Throws InputError if it cannot be created (unwritable
    /// directory): callers open every output before simulating so this is a bad-input error.
    explicit AtomicFile(std::filesystem::path final_path);
    ~AtomicFile() override;
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    /// Throws RunError on I/O failure (disk full, ...).
    void write(std::string_view bytes) override;
    /// Flushes, syncs, closes and renames to the final name. Throws RunError on failure.
    void commit();

    const std::filesystem::path& finalPath() const { return final_path_; }
    const std::filesystem::path& tempPath() const { return temp_path_; }

private:
    std::filesystem::path final_path_;
    std::filesystem::path temp_path_;
    std::FILE* file_ = nullptr;   ///< owned; null once committed
};

/// Makes `dir` ready to receive a run: creates it (and parents) if missing, checks that a file can
/// be created in it, and removes a run.json left there by an earlier run so the directory stops
/// looking complete before any of its files are replaced. Returns true if it created `dir`.
/// Throws InputError with one line naming the directory and the reason.
bool prepareOutputDirectory(const std::filesystem::path& dir);

/// Removes `dir` if it is empty (after a failed run in a directory prepareOutputDirectory made).
void removeIfEmpty(const std::filesystem::path& dir) noexcept;

}  // namespace vroc::recording
