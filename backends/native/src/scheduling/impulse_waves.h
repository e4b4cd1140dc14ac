// SPDX-License-Identifier: MIT
// ImpulseWaves: a sequential pass over an island's contacts (the collision phase's Gauss-Seidel
// sweeps, each contact's impulse seeing every earlier one's), cut into waves that workers may share
// without changing a bit of its result. A contact's wave is one past the latest wave of an earlier
// contact that shares a movable body with it. So no two contacts of a wave share a movable body
// (they commute: each reads and writes only its own bodies, and the immovable ones are only read),
// and every contact comes after each earlier one it depends on, as in the sequential pass. Unlike
// a colouring, the order of dependent contacts is the sequential one: the results are those of the
// one-worker pass, bit for bit, for any number of workers.
#pragma once

#include <cstddef>
#include <vector>

#include "dynamics/contact.h"
#include "dynamics/rigid_body.h"

namespace vroc::native {

struct ImpulseWaves {
    std::vector<int> order;           ///< contact indices, wave by wave, ascending within a wave
    std::vector<std::size_t> begin;   ///< wave w is order[begin[w], begin[w + 1])
    std::vector<int> wave_of;         ///< per contact (scratch, kept between calls)
    std::vector<int> last_wave;       ///< per body (scratch)
    std::vector<std::size_t> fill;    ///< per wave: its next free slot in `order` (scratch)

    std::size_t waves() const { return begin.empty() ? 0 : begin.size() - 1; }
};

/// The waves of `manifolds` in their order; a body of infinite mass links no two contacts.
/// Allocation-free once `waves` has held an island this large.
void scheduleImpulseWaves(const std::vector<ContactManifold>& manifolds, const std::vector<RigidBody>& bodies,
                          ImpulseWaves& waves);

}  // namespace vroc::native
