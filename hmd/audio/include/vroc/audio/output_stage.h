// SPDX-License-Identifier: MIT
// Brings the mix within full scale [-1, 1] before it is written (sound_settings.h: OutputLevel).
#pragma once

#include <cstddef>
#include <span>
#include <string>

#include "vroc/audio/sound_settings.h"

namespace vroc::audio {

struct OutputStageReport {
    OutputLevel level = OutputLevel::Normalize;
    double input_peak = 0;       ///< [-] largest |sample| of the mix
    double gain = 1;             ///< [-] applied to every sample
    std::size_t limited = 0;     ///< Fixed: samples the soft limiter changed
    double output_peak = 0;      ///< [-] largest |sample| written
    /// One line for run output, e.g. "normalised: peak 3.2 -> -1 dBFS (gain -20.1 dB)".
    std::string describe() const;
};

/// Normalize: samples *= normalize_peak / peak (nothing when the track is silent). Fixed:
/// x = fixed_gain * sample, then |x| > k becomes sign(x) (k + (1 - k) tanh((|x| - k) / (1 - k))),
/// k = limiter_knee: continuous with slope 1 at the knee, monotonic, below 1 (so impulse order
/// is kept).
OutputStageReport applyOutputStage(std::span<float> samples, const SoundSettings& settings);

}  // namespace vroc::audio
