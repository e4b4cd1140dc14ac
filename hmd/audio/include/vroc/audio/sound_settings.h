// SPDX-License-Identifier: MIT
// Settings of the impact sound (docs/hmd.md#impact-sound): sample rate, the impulse -> amplitude
// scale, which impacts stay silent, and the output stage that keeps samples within full scale.
#pragma once

#include <string>

namespace vroc::audio {

/// How the mix is brought within full scale [-1, 1].
enum class OutputLevel {
    Normalize,   ///< the whole track scaled so its peak is `normalize_peak` (silence stays silence)
    Fixed,       ///< scaled by `fixed_gain`, then a soft limiter above `limiter_knee` (levels comparable
                 ///< between runs: the same impulse gives the same sample value)
};

/// "normalize" or "fixed".
const char* outputLevelName(OutputLevel level);
/// Parses outputLevelName's words; throws InputError naming `option` otherwise.
OutputLevel parseOutputLevel(const std::string& text, const std::string& option);

struct SoundSettings {
    static constexpr int kMinSampleRate = 44100;    ///< [Hz] MaterialSound::kMaxModeHz is below its Nyquist
    static constexpr int kMaxSampleRate = 192000;   ///< [Hz]

    int sample_rate = 48000;           ///< [Hz] in [kMinSampleRate, kMaxSampleRate]; mono, 16-bit PCM WAV
    /// [N s] impulse that excites each mode with its material gain as amplitude: an impact of impulse
    /// J adds (J / reference_impulse) * (h_a + h_b) / 2 to the mix (impact_synth.h).
    double reference_impulse = 1.0;
    /// [-] an impact is quiet (silent) when its impulse is below this many times the weight impulse
    /// of one frame, m |g| frame_dt, m the mass of the lighter virtual body of the pair: a contact
    /// that starts at rest, or a resting contact that reopens and closes (chatter), carries about
    /// one such impulse per frame (a box set down on a floor: native reports exactly m |g| dt,
    /// Bullet and ODE within 0.003 %), an audible impact several. 0 sounds every impact.
    double quiet_weight_frames = 2.0;
    /// [s] >= 0: an impact of a pair within this time after that pair's previous sounded impact is
    /// silent, so a contact that keeps producing events gives at most 1/refractory impacts per
    /// second instead of noise.
    double refractory = 0.010;
    OutputLevel level = OutputLevel::Normalize;
    double normalize_peak = 0.8912509381337456;   ///< [-] full scale: -1 dBFS
    double fixed_gain = 1.0;                      ///< [-] Fixed: mix -> full scale
    double limiter_knee = 0.5;                    ///< [-] Fixed: |x| above this is compressed smoothly towards 1
    /// [s] after the last frame the track goes on while the sounded materials ring, until their
    /// slowest mode has fallen by 60 dB, but at most this long.
    double max_tail = 2.0;
    /// [s] longest run accepted for sound (the track is this plus the tail at most): the mix is held
    /// in memory, 4 bytes a sample (110 MB for 600 s at 48 kHz).
    double max_duration = 600.0;
};

/// Throws InputError ("sound settings: <field>: expected ...") for a value out of range.
void validate(const SoundSettings& settings);

}  // namespace vroc::audio
