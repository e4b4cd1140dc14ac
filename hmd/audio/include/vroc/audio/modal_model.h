// SPDX-License-Identifier: MIT
// The modal model of one material: a few damped sinusoids. Struck by a unit excitation at tau = 0
// it rings as h(tau) = sum_i g_i e^(-d_i tau) cos(2 pi f_i tau) for tau >= 0 (0 before): each mode
// is a damped oscillator hit by an impulse, and h is its velocity, which jumps at the hit (so an
// onset is sharp to the sample).
#pragma once

#include <string>
#include <vector>

#include "vroc/core/scene.h"

namespace vroc::audio {

struct Mode {
    double frequency_hz = 0;   ///< [Hz] f > 0
    double decay_per_s = 0;    ///< [1/s] d > 0: the amplitude falls as e^(-d tau)
    double gain = 0;           ///< [-] g >= 0
};

class ModalModel {
public:
    /// Checks `sound` as the scene loader does (a scene built in code skips the loader): equal
    /// lengths, ranges of MaterialSound. Throws InputError naming `material_name`.
    ModalModel(const MaterialSound& sound, const std::string& material_name);

    const std::vector<Mode>& modes() const { return modes_; }
    /// [-] sum of the gains: h(0).
    double gainSum() const;
    /// [s] time after which every mode has fallen by `decibels` (> 0) of amplitude.
    double ringTime(double decibels) const;
    /// h(tau), the closed form above (for checks; the synthesiser runs the modes recursively).
    double response(double tau) const;

private:
    std::vector<Mode> modes_;
};

}  // namespace vroc::audio
