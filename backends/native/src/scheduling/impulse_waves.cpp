// SPDX-License-Identifier: MIT
#include "scheduling/impulse_waves.h"

#include <algorithm>
#include <cassert>

namespace vroc::native {

void scheduleImpulseWaves(const std::vector<ContactManifold>& manifolds, const std::vector<RigidBody>& bodies,
                          ImpulseWaves& waves) {
    waves.order.clear();
    waves.begin.clear();
    waves.wave_of.resize(manifolds.size());
    waves.last_wave.assign(bodies.size(), -1);
    int count = 0;   // waves so far
    for (std::size_t k = 0; k < manifolds.size(); ++k) {
        const int a = manifolds[k].body_a, b = manifolds[k].body_b;
        const bool move_a = !bodies[static_cast<std::size_t>(a)].infiniteMass();
        const bool move_b = !bodies[static_cast<std::size_t>(b)].infiniteMass();
        int wave = 0;
        if (move_a) wave = std::max(wave, waves.last_wave[static_cast<std::size_t>(a)] + 1);
        if (move_b) wave = std::max(wave, waves.last_wave[static_cast<std::size_t>(b)] + 1);
        if (move_a) waves.last_wave[static_cast<std::size_t>(a)] = wave;
        if (move_b) waves.last_wave[static_cast<std::size_t>(b)] = wave;
        waves.wave_of[k] = wave;
        count = std::max(count, wave + 1);
    }
    // Counting sort by wave, stable: ascending contact index within a wave.
    waves.begin.assign(static_cast<std::size_t>(count) + 1, 0);
    for (std::size_t k = 0; k < manifolds.size(); ++k) ++waves.begin[static_cast<std::size_t>(waves.wave_of[k]) + 1];
    for (std::size_t w = 0; w < static_cast<std::size_t>(count); ++w) waves.begin[w + 1] += waves.begin[w];
    waves.order.resize(manifolds.size());
    waves.fill.assign(waves.begin.begin(), waves.begin.end() - 1);
    for (std::size_t k = 0; k < manifolds.size(); ++k)
        waves.order[waves.fill[static_cast<std::size_t>(waves.wave_of[k])]++] = static_cast<int>(k);
    assert(waves.begin.back() == manifolds.size());
}

}  // namespace vroc::native
