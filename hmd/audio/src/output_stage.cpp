// SPDX-License-Identifier: MIT
#include "vroc/audio/output_stage.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace vroc::audio {
namespace {

double decibels(double ratio) { return 20.0 * std::log10(ratio); }

double peakOf(std::span<const float> samples) {
    double peak = 0;
    for (float s : samples) peak = std::max(peak, static_cast<double>(std::fabs(s)));
    return peak;
}

}  // namespace

std::string OutputStageReport::describe() const {
    if (level == OutputLevel::Normalize) {
        if (input_peak == 0) return "normalised: silent track, left silent";
        return fmt::format("normalised: peak {:.4g} -> {:.1f} dBFS (gain {:+.1f} dB)", input_peak,
                           decibels(output_peak), decibels(gain));
    }
    return fmt::format("fixed level (gain {:.4g}), soft limiter: {} samples limited, peak {:.4g} -> {:.4g}", gain,
                       limited, input_peak * gain, output_peak);
}

OutputStageReport applyOutputStage(std::span<float> samples, const SoundSettings& settings) {
    OutputStageReport report;
    report.level = settings.level;
    report.input_peak = peakOf(samples);
    if (settings.level == OutputLevel::Normalize) {
        report.gain = report.input_peak > 0 ? settings.normalize_peak / report.input_peak : 1.0;
        for (float& s : samples) s = static_cast<float>(s * report.gain);
    } else {
        report.gain = settings.fixed_gain;
        const double k = settings.limiter_knee;
        for (float& s : samples) {
            const double x = s * report.gain;
            const double magnitude = std::fabs(x);
            if (magnitude <= k) {
                s = static_cast<float>(x);
                continue;
            }
            ++report.limited;
            s = static_cast<float>(std::copysign(k + (1 - k) * std::tanh((magnitude - k) / (1 - k)), x));
        }
    }
    report.output_peak = peakOf(samples);
    return report;
}

}  // namespace vroc::audio
