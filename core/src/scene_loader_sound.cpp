// SPDX-License-Identifier: MIT
// The optional `sound` object of a material (docs/scene-format.md#materials): its modes for the
// impact sound synthesiser (hmd/audio). Strict like the rest of the loader: every error names the
// field and says what was expected.
#include <fmt/format.h>

#include "scene_loader_internal.h"

namespace vroc {
namespace {

// A non-empty array of at most kMaxSoundModes numbers, each checked by `check`.
template <typename Check>
std::vector<double> readModeArray(const JsonReader& r, Check check) {
    const std::size_t n = r.arraySize();
    if (n < 1 || n > MaterialSound::kMaxSoundModes)
        r.fail(fmt::format("expected an array of 1 to {} numbers (one per mode), got {} entries",
                           MaterialSound::kMaxSoundModes, n));
    std::vector<double> values;
    for (std::size_t i = 0; i < n; ++i) values.push_back(check(r.element(i)));
    return values;
}

}  // namespace

MaterialSound readMaterialSound(const JsonReader& r) {
    r.requireObject({"modes_hz", "decay_per_s", "gains"});
    MaterialSound sound;
    const JsonReader modes = r.at("modes_hz");
    sound.modes_hz = readModeArray(modes, [](const JsonReader& v) {
        const double f = v.positive(" [Hz]");
        if (f > MaterialSound::kMaxModeHz)
            v.fail(fmt::format("expected a frequency in (0, {}] Hz (below the Nyquist frequency of 44.1 kHz, the "
                               "lowest sample rate of the sound output), got {}", MaterialSound::kMaxModeHz, f));
        return f;
    });
    const auto sameLength = [&](const JsonReader& array) {
        const std::size_t n = array.arraySize();
        if (n != sound.modes_hz.size())
            array.fail(
                fmt::format("expected {} entries (one per entry of modes_hz), got {}", sound.modes_hz.size(), n));
    };
    const JsonReader decay = r.at("decay_per_s");
    sameLength(decay);
    sound.decay_per_s = readModeArray(decay, [](const JsonReader& v) {
        return v.inRange(MaterialSound::kMinDecayPerS, MaterialSound::kMaxDecayPerS, " [1/s]");
    });
    const JsonReader gains = r.at("gains");
    sameLength(gains);
    sound.gains = readModeArray(gains, [](const JsonReader& v) { return v.nonNegative(""); });
    return sound;
}

}  // namespace vroc
