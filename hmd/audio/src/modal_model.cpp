// SPDX-License-Identifier: MIT
#include "vroc/audio/modal_model.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "vroc/core/errors.h"

namespace vroc::audio {

ModalModel::ModalModel(const MaterialSound& sound, const std::string& material_name) {
    const auto fail = [&](const std::string& what) {
        throw InputError(fmt::format("material `{}`: sound: {}", material_name, what));
    };
    const std::size_t n = sound.modes_hz.size();
    if (n < 1 || n > MaterialSound::kMaxSoundModes)
        fail(fmt::format("expected 1 to {} modes, got {}", MaterialSound::kMaxSoundModes, n));
    if (sound.decay_per_s.size() != n || sound.gains.size() != n)
        fail(fmt::format("modes_hz, decay_per_s and gains must have equal lengths, got {}, {} and {}", n,
                         sound.decay_per_s.size(), sound.gains.size()));
    for (std::size_t i = 0; i < n; ++i) {
        const Mode m{sound.modes_hz[i], sound.decay_per_s[i], sound.gains[i]};
        if (!(m.frequency_hz > 0 && m.frequency_hz <= MaterialSound::kMaxModeHz))
            fail(fmt::format("modes_hz[{}]: expected a frequency in (0, {}] Hz, got {}", i, MaterialSound::kMaxModeHz,
                             m.frequency_hz));
        if (!(m.decay_per_s >= MaterialSound::kMinDecayPerS && m.decay_per_s <= MaterialSound::kMaxDecayPerS))
            fail(fmt::format("decay_per_s[{}]: expected a number in [{}, {}] [1/s], got {}", i,
                             MaterialSound::kMinDecayPerS, MaterialSound::kMaxDecayPerS, m.decay_per_s));
        if (!(m.gain >= 0 && std::isfinite(m.gain)))
            fail(fmt::format("gains[{}]: expected a finite number >= 0, got {}", i, m.gain));
        modes_.push_back(m);
    }
}

double ModalModel::gainSum() const {
    double sum = 0;
    for (const Mode& m : modes_) sum += m.gain;
    return sum;
}

double ModalModel::ringTime(double decibels) const {
    // Amplitude ratio 10^(-dB/20) = e^(-d t): t = dB ln(10) / (20 d), longest for the slowest mode.
    double slowest = modes_.front().decay_per_s;
    for (const Mode& m : modes_) slowest = std::min(slowest, m.decay_per_s);
    return decibels * std::numbers::ln10 / (20.0 * slowest);
}

double ModalModel::response(double tau) const {
    if (tau < 0) return 0;
    double sum = 0;
    for (const Mode& m : modes_)
        sum += m.gain * std::exp(-m.decay_per_s * tau) * std::cos(2 * std::numbers::pi * m.frequency_hz * tau);
    return sum;
}

}  // namespace vroc::audio
