// SPDX-License-Identifier: MIT
#include "vroc/core/recording/atomic_output.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>

#include "vroc/core/errors.h"

namespace vroc::recording {
namespace fs = std::filesystem;

AtomicFile::AtomicFile(fs::path final_path) : final_path_(std::move(final_path)) {
    temp_path_ = final_path_;
    temp_path_ += ".tmp";
    file_ = std::fopen(temp_path_.c_str(), "wb");
    if (!file_)
        throw InputError("cannot write output file '" + temp_path_.string() + "': " + std::strerror(errno));
}

AtomicFile::~AtomicFile() {
    if (!file_) return;
    std::fclose(file_);
    std::error_code ignored;
    fs::remove(temp_path_, ignored);
}

void AtomicFile::write(std::string_view bytes) {
    if (!file_) throw std::logic_error("AtomicFile::write after commit: " + final_path_.string());
    if (std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size())
        throw RunError("writing '" + temp_path_.string() + "' failed: " + std::strerror(errno));
}

void AtomicFile::commit() {
    if (!file_) throw std::logic_error("AtomicFile committed twice: " + final_path_.string());
    // fsync before rename: after a crash the final name never points at a file with missing data.
    bool ok = std::fflush(file_) == 0 && ::fsync(::fileno(file_)) == 0;
    const int flush_errno = errno;
    ok = (std::fclose(file_) == 0) && ok;
    file_ = nullptr;
    if (!ok) {
        std::error_code ignored;
        fs::remove(temp_path_, ignored);
        throw RunError("writing '" + temp_path_.string() + "' failed: " + std::strerror(flush_errno));
    }
    std::error_code ec;
    fs::rename(temp_path_, final_path_, ec);
    if (ec) {
        fs::remove(temp_path_, ec);
        throw RunError("cannot rename '" + temp_path_.string() + "' to '" + final_path_.string() + "': " + ec.message());
    }
}

bool prepareOutputDirectory(const fs::path& dir) {
    const std::string where = "output directory '" + dir.string() + "'";
    std::error_code ec;
    const bool existed = fs::exists(dir, ec);
    if (existed && !fs::is_directory(dir, ec)) throw InputError(where + ": exists and is not a directory");
    if (!existed) {
        fs::create_directories(dir, ec);
        if (ec) throw InputError(where + ": cannot create it: " + ec.message());
    }
    // access() alone is not enough (read-only mounts, ACLs, root): create a real file.
    const fs::path probe = dir / (".vroc-write-test-" + std::to_string(::getpid()));
    std::FILE* f = std::fopen(probe.c_str(), "wb");
    if (!f) {
        const std::string reason = std::strerror(errno);
        if (!existed) removeIfEmpty(dir);
        throw InputError(where + ": not writable: " + reason);
    }
    std::fclose(f);
    fs::remove(probe, ec);
    fs::remove(dir / "run.json", ec);
    if (ec) throw InputError(where + ": cannot remove the run.json of an earlier run: " + ec.message());
    return !existed;
}

void removeIfEmpty(const fs::path& dir) noexcept {
    std::error_code ec;
    if (fs::is_directory(dir, ec) && fs::is_empty(dir, ec)) fs::remove(dir, ec);
}

}  // namespace vroc::recording
