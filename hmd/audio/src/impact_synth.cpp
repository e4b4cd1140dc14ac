// SPDX-License-Identifier: MIT
#include "vroc/audio/impact_synth.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "vroc/audio/sound_settings.h"
#include "vroc/core/errors.h"

namespace vroc::audio {
namespace {

// A mode below this fraction of its largest excitation (-200 dB) is silent: it is set to zero,
// which keeps subnormal numbers out of the recursion and lets the loop jump to the next excitation.
constexpr double kSilent = 1e-10;

struct Excitation {
    std::size_t sample;   // onset sample n0
    double re, im;        // complex amplitude of the mode at n0
};

}  // namespace

ImpactSynth::ImpactSynth(std::vector<ModalModel> materials, int sample_rate)
    : materials_(std::move(materials)), sample_rate_(sample_rate) {
    if (sample_rate < SoundSettings::kMinSampleRate || sample_rate > SoundSettings::kMaxSampleRate)
        throw InputError(fmt::format("sample rate: expected an integer in [{}, {}] Hz, got {}",
                                     SoundSettings::kMinSampleRate, SoundSettings::kMaxSampleRate, sample_rate));
}

std::size_t ImpactSynth::onsetSample(double time) const {
    return static_cast<std::size_t>(std::ceil(time * sample_rate_));
}

void ImpactSynth::add(const Impact& impact) {
    const int n = static_cast<int>(materials_.size());
    if (!std::isfinite(impact.time) || impact.time < 0 || !std::isfinite(impact.amplitude) || impact.amplitude < 0 ||
        impact.material_a < 0 || impact.material_a >= n || impact.material_b < 0 || impact.material_b >= n)
        throw std::invalid_argument(fmt::format("ImpactSynth::add: bad impact at t = {} (amplitude {}, materials {}, "
                                                "{})", impact.time, impact.amplitude, impact.material_a,
                                                impact.material_b));
    impacts_.push_back(impact);
}

std::vector<float> ImpactSynth::render(std::size_t count) const {
    std::vector<float> out(count, 0.0f);
    const double fs = sample_rate_;
    // Impacts by onset sample; stable, so equal onsets keep the order added.
    std::vector<Impact> sorted = impacts_;
    std::stable_sort(sorted.begin(), sorted.end(), [](const Impact& a, const Impact& b) { return a.time < b.time; });

    std::vector<Excitation> excitations;
    for (std::size_t m = 0; m < materials_.size(); ++m) {
        for (const Mode& mode : materials_[m].modes()) {
            const double omega = 2 * std::numbers::pi * mode.frequency_hz;   // [rad/s]
            excitations.clear();
            for (const Impact& impact : sorted) {
                // Each body of the pair excites its own material with half the amplitude.
                const double weight = 0.5 * ((impact.material_a == static_cast<int>(m)) +
                                             (impact.material_b == static_cast<int>(m)));
                const std::size_t n0 = onsetSample(impact.time);
                if (weight == 0 || n0 >= count || impact.amplitude == 0 || mode.gain == 0) continue;
                // Sub-sample phase: the mode started at t, so at n0 it is already tau0 old.
                const double tau0 = std::max(0.0, static_cast<double>(n0) / fs - impact.time);
                const double a = impact.amplitude * weight * mode.gain * std::exp(-mode.decay_per_s * tau0);
                excitations.push_back({n0, a * std::cos(omega * tau0), a * std::sin(omega * tau0)});
            }
            if (excitations.empty()) continue;
            double loudest = 0;
            for (const Excitation& e : excitations) loudest = std::max(loudest, std::hypot(e.re, e.im));
            const double silent2 = (kSilent * loudest) * (kSilent * loudest);
            // One sample of the mode: z -> z e^((-d + i omega) / fs).
            const double decay = std::exp(-mode.decay_per_s / fs);
            const double r_re = decay * std::cos(omega / fs), r_im = decay * std::sin(omega / fs);
            double z_re = 0, z_im = 0;
            std::size_t next = 0;
            std::size_t n = excitations.front().sample;
            while (n < count) {
                while (next < excitations.size() && excitations[next].sample == n) {
                    z_re += excitations[next].re;
                    z_im += excitations[next].im;
                    ++next;
                }
                out[n] += static_cast<float>(z_re);
                const double re = z_re * r_re - z_im * r_im;
                z_im = z_re * r_im + z_im * r_re;
                z_re = re;
                ++n;
                if (z_re * z_re + z_im * z_im < silent2) {
                    z_re = z_im = 0;
                    if (next == excitations.size()) break;
                    n = std::max(n, excitations[next].sample);
                }
            }
        }
    }
    return out;
}

}  // namespace vroc::audio
