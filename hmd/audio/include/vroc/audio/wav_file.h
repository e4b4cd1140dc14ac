// SPDX-License-Identifier: MIT
// WAV files through libsndfile: mono, 16-bit PCM. Written atomically: "<path>.tmp", synced, then
// renamed, so a failed or interrupted write never leaves a file that looks complete.
#pragma once

#include <filesystem>
#include <span>
#include <vector>

namespace vroc::audio {

/// Checks that `path` can be written before any work is done: creates its directory if missing
/// (as `vroc run --out` does), creates and removes "<path>.tmp", refuses a directory. Throws
/// InputError "<what> '<path>': <reason>".
void checkWritable(const std::filesystem::path& path, const char* what);

/// Writes `samples` (full scale [-1, 1]; libsndfile clips beyond) at `sample_rate` [Hz]. Throws
/// RunError with libsndfile's or the system's reason; the temporary file is then removed.
void writeWav(const std::filesystem::path& path, std::span<const float> samples, int sample_rate);

struct WavData {
    int sample_rate = 0;          ///< [Hz]
    int channels = 0;
    std::vector<float> samples;   ///< interleaved, full scale [-1, 1]
};
/// Reads any file libsndfile reads. Throws InputError "<path>: <reason>".
WavData readWav(const std::filesystem::path& path);

}  // namespace vroc::audio
