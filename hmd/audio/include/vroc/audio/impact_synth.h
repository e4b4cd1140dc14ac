// SPDX-License-Identifier: MIT
// Turns impacts into samples. An impact at time t [s] of amplitude a = J / reference_impulse
// between bodies of materials A and B adds
//     a * (h_A(tau) + h_B(tau)) / 2,   tau = n / sample_rate - t,
// to sample n (modal_model.h: h is 0 before tau = 0), so its first sample is the first at or after
// t: n0 = ceil(t * sample_rate), sample-exact, with the sub-sample phase kept. Amplitude is linear
// in the impulse (a linear modal model struck by an impulse); the impact's position on the bodies
// does not change it. Units: samples are dimensionless, 1 being full scale before the output stage.
// Deterministic: the same impacts give the same bits.
#pragma once

#include <cstddef>
#include <vector>

#include "vroc/audio/modal_model.h"

namespace vroc::audio {

struct Impact {
    double time = 0;        ///< [s] >= 0, finite
    double amplitude = 0;   ///< [-] J / reference_impulse
    int material_a = 0;     ///< indices into the synthesiser's materials
    int material_b = 0;
};

class ImpactSynth {
public:
    /// `materials` by scene material index. Throws InputError unless sample_rate is in
    /// [SoundSettings::kMinSampleRate, kMaxSampleRate].
    ImpactSynth(std::vector<ModalModel> materials, int sample_rate);

    /// Throws std::invalid_argument for a non-finite or negative time or amplitude, or a material
    /// index out of range.
    void add(const Impact& impact);
    /// The mix y[n] for n in [0, count). Each mode of each struck material runs as one complex
    /// one-pole recursion z[n] = z[n-1] r + (excitations at n), y += Re z: the cost is modes x
    /// samples whatever the number of impacts, with no truncated tails.
    std::vector<float> render(std::size_t count) const;

    int sampleRate() const { return sample_rate_; }
    const std::vector<ModalModel>& materials() const { return materials_; }
    const std::vector<Impact>& impacts() const { return impacts_; }
    /// First sample of an impact at `time` [s]: ceil(time * sample_rate).
    std::size_t onsetSample(double time) const;

private:
    std::vector<ModalModel> materials_;
    int sample_rate_;
    std::vector<Impact> impacts_;   ///< in the order added (time order)
};

}  // namespace vroc::audio
