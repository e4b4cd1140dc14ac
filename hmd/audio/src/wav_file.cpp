// SPDX-License-Identifier: MIT
#include "vroc/audio/wav_file.h"

#include <sndfile.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>

#include "vroc/core/errors.h"

namespace vroc::audio {
namespace fs = std::filesystem;

namespace {

fs::path tempPath(const fs::path& path) {
    fs::path temp = path;
    temp += ".tmp";
    return temp;
}

// Closes the file and removes the temporary one unless released (every early exit cleans up).
class TempSndFile {
public:
    TempSndFile(const fs::path& temp, SNDFILE* file) : temp_(temp), file_(file) {}
    ~TempSndFile() {
        if (file_) sf_close(file_);
        if (!released_) {
            std::error_code ignored;
            fs::remove(temp_, ignored);
        }
    }
    TempSndFile(const TempSndFile&) = delete;
    TempSndFile& operator=(const TempSndFile&) = delete;
    SNDFILE* get() const { return file_; }
    /// Closes; returns libsndfile's error text or "".
    std::string close() {
        const int rc = sf_close(file_);
        file_ = nullptr;
        return rc == 0 ? "" : sf_error_number(rc);
    }
    void release() { released_ = true; }

private:
    fs::path temp_;
    SNDFILE* file_;
    bool released_ = false;
};

}  // namespace

void checkWritable(const fs::path& path, const char* what) {
    const std::string where = std::string(what) + " '" + path.string() + "'";
    std::error_code ec;
    if (path.empty()) throw InputError(std::string(what) + ": expected a file path");
    if (fs::is_directory(path, ec)) throw InputError(where + ": is a directory (expected a file path)");
    if (const fs::path parent = path.parent_path(); !parent.empty() && !fs::exists(parent, ec)) {
        fs::create_directories(parent, ec);
        if (ec) throw InputError(where + ": cannot create its directory: " + ec.message());
    }
    const fs::path temp = tempPath(path);
    std::FILE* f = std::fopen(temp.c_str(), "wb");
    if (!f) throw InputError(where + ": cannot write there: " + std::strerror(errno));
    std::fclose(f);
    fs::remove(temp, ec);
}

void writeWav(const fs::path& path, std::span<const float> samples, int sample_rate) {
    const fs::path temp = tempPath(path);
    const std::string where = "writing '" + path.string() + "'";
    SF_INFO info{};
    info.samplerate = sample_rate;
    info.channels = 1;
    info.format = SF_FORMAT_WAV | SF_FORMAT_PCM_16;
    SNDFILE* raw = sf_open(temp.c_str(), SFM_WRITE, &info);
    if (!raw) {
        const std::string reason = sf_strerror(nullptr);
        std::error_code ignored;
        fs::remove(temp, ignored);
        throw RunError(where + " failed: " + reason);
    }
    TempSndFile file(temp, raw);
    // Beyond full scale clips instead of wrapping around (the output stage keeps within it anyway).
    sf_command(file.get(), SFC_SET_CLIPPING, nullptr, SF_TRUE);
    const sf_count_t written = sf_writef_float(file.get(), samples.data(), static_cast<sf_count_t>(samples.size()));
    if (written != static_cast<sf_count_t>(samples.size()))
        throw RunError(where + " failed: " + sf_strerror(file.get()));
    sf_write_sync(file.get());   // fsync before rename: the final name never points at missing data
    if (const std::string error = file.close(); !error.empty()) throw RunError(where + " failed: " + error);
    std::error_code ec;
    fs::rename(temp, path, ec);
    if (ec) throw RunError("cannot rename '" + temp.string() + "' to '" + path.string() + "': " + ec.message());
    file.release();
}

WavData readWav(const fs::path& path) {
    SF_INFO info{};
    SNDFILE* file = sf_open(path.c_str(), SFM_READ, &info);
    if (!file) throw InputError(path.string() + ": cannot read as a sound file: " + sf_strerror(nullptr));
    WavData data;
    data.sample_rate = info.samplerate;
    data.channels = info.channels;
    data.samples.resize(static_cast<std::size_t>(info.frames) * static_cast<std::size_t>(info.channels));
    const sf_count_t got = sf_readf_float(file, data.samples.data(), info.frames);
    sf_close(file);
    if (got != info.frames)
        throw InputError(path.string() + ": read " + std::to_string(got) + " of " + std::to_string(info.frames) +
                         " frames");
    return data;
}

}  // namespace vroc::audio
