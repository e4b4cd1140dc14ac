// SPDX-License-Identifier: MIT
// ImpulseWaves against the definition, checked pair by pair (brute force): the waves hold every
// contact once, no wave holds two contacts sharing a movable body, and of two contacts sharing one
// the earlier is in an earlier wave (so a wave-by-wave pass is the sequential pass, bit for bit).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "scheduling/impulse_waves.h"

namespace vroc::native {
namespace {

struct Island {
    std::vector<RigidBody> bodies;
    std::vector<ContactManifold> manifolds;
};

// `bodies` bodies, the first `fixed` of infinite mass (static, or tracked), `contacts` random pairs.
Island randomIsland(std::mt19937_64& rng, int bodies, int fixed, int contacts) {
    Island is;
    is.bodies.resize(static_cast<std::size_t>(bodies));
    for (int i = 0; i < bodies; ++i) {
        RigidBody& b = is.bodies[static_cast<std::size_t>(i)];
        if (i < fixed) {
            b.is_static = i % 2 == 0;
            b.is_kinematic = i % 2 == 1;
        } else {
            b.inv_mass = 1.0;
        }
    }
    std::uniform_int_distribution<int> pick(0, bodies - 1);
    for (int k = 0; k < contacts; ++k) {
        ContactManifold& m = is.manifolds.emplace_back();
        m.body_a = pick(rng);
        do m.body_b = pick(rng); while (m.body_b == m.body_a);
    }
    return is;
}

TEST(SchedulingImpulseWaves, WavesKeepTheSequentialOrderOfEveryDependentPair) {
    std::mt19937_64 rng(2026);
    ImpulseWaves waves;   // reused, as the island stage reuses it
    for (int trial = 0; trial < 200; ++trial) {
        const int bodies = 2 + trial % 40, fixed = trial % 3, contacts = 1 + (trial * 7) % 150;
        const Island is = randomIsland(rng, bodies, std::min(fixed, bodies - 1), contacts);
        scheduleImpulseWaves(is.manifolds, is.bodies, waves);
        const std::size_t n = is.manifolds.size();
        ASSERT_EQ(waves.order.size(), n);
        ASSERT_EQ(waves.begin.front(), 0u);
        ASSERT_EQ(waves.begin.back(), n);
        std::vector<int> wave(n, -1);
        for (std::size_t w = 0; w < waves.waves(); ++w) {
            ASSERT_LT(waves.begin[w], waves.begin[w + 1]) << "an empty wave";
            for (std::size_t i = waves.begin[w]; i < waves.begin[w + 1]; ++i) {
                const auto k = static_cast<std::size_t>(waves.order[i]);
                ASSERT_LT(k, n);
                ASSERT_EQ(wave[k], -1) << "contact " << k << " twice";
                wave[k] = static_cast<int>(w);
                if (i > waves.begin[w]) {
                    EXPECT_LT(waves.order[i - 1], waves.order[i]) << "a wave in contact order";
                }
            }
        }
        auto movable = [&](int body) { return !is.bodies[static_cast<std::size_t>(body)].infiniteMass(); };
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j) {
                const ContactManifold &x = is.manifolds[i], &y = is.manifolds[j];
                bool shared = false;
                for (int b : {x.body_a, x.body_b})
                    shared = shared || (movable(b) && (b == y.body_a || b == y.body_b));
                if (shared) {
                    EXPECT_LT(wave[i], wave[j]) << "trial " << trial << ": contacts " << i << " and " << j
                                                << " share a movable body";
                }
            }
    }
}

TEST(SchedulingImpulseWaves, ContactsOnlyThroughImmovableBodiesFormOneWave) {
    std::mt19937_64 rng(7);
    Island is = randomIsland(rng, 12, 2, 0);
    for (int b = 2; b < 12; ++b) {   // every movable body on the static and the tracked one
        ContactManifold& m = is.manifolds.emplace_back();
        m.body_a = b % 2;
        m.body_b = b;
    }
    ImpulseWaves waves;
    scheduleImpulseWaves(is.manifolds, is.bodies, waves);
    EXPECT_EQ(waves.waves(), 1u);
}

}  // namespace
}  // namespace vroc::native
