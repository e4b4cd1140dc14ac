// SPDX-License-Identifier: MIT
#include "vroc/audio/sound_settings.h"

#include <cmath>

#include <fmt/format.h>

#include "vroc/core/errors.h"

namespace vroc::audio {

const char* outputLevelName(OutputLevel level) {
    return level == OutputLevel::Normalize ? "normalize" : "fixed";
}

OutputLevel parseOutputLevel(const std::string& text, const std::string& option) {
    if (text == "normalize") return OutputLevel::Normalize;
    if (text == "fixed") return OutputLevel::Fixed;
    throw InputError(fmt::format("{}: expected \"normalize\" (peak at -1 dBFS) or \"fixed\" (same impulse, same "
                                 "level; soft limiter), got \"{}\"", option, text));
}

void validate(const SoundSettings& s) {
    const auto fail = [](const char* field, const std::string& expected, double got) {
        throw InputError(fmt::format("sound settings: {}: expected {}, got {}", field, expected, got));
    };
    const auto finite = [](double v) { return std::isfinite(v); };
    if (s.sample_rate < SoundSettings::kMinSampleRate || s.sample_rate > SoundSettings::kMaxSampleRate)
        fail("sample_rate", fmt::format("an integer in [{}, {}] Hz", SoundSettings::kMinSampleRate,
                                        SoundSettings::kMaxSampleRate), s.sample_rate);
    if (!finite(s.reference_impulse) || s.reference_impulse <= 0)
        fail("reference_impulse", "a number > 0 [N s]", s.reference_impulse);
    if (!finite(s.quiet_weight_frames) || s.quiet_weight_frames < 0)
        fail("quiet_weight_frames", "a number >= 0", s.quiet_weight_frames);
    if (!finite(s.refractory) || s.refractory < 0) fail("refractory", "a number >= 0 [s]", s.refractory);
    if (!finite(s.normalize_peak) || s.normalize_peak <= 0 || s.normalize_peak > 1)
        fail("normalize_peak", "a number in (0, 1]", s.normalize_peak);
    if (!finite(s.fixed_gain) || s.fixed_gain <= 0) fail("fixed_gain", "a number > 0", s.fixed_gain);
    if (!finite(s.limiter_knee) || s.limiter_knee <= 0 || s.limiter_knee >= 1)
        fail("limiter_knee", "a number in (0, 1)", s.limiter_knee);
    if (!finite(s.max_tail) || s.max_tail < 0) fail("max_tail", "a number >= 0 [s]", s.max_tail);
    if (!finite(s.max_duration) || s.max_duration <= 0) fail("max_duration", "a number > 0 [s]", s.max_duration);
}

}  // namespace vroc::audio
