// SPDX-License-Identifier: MIT
// What an engine's contacts say after an internal step, and the collision event a pair's contacts
// make (docs/events.md): the vocabulary of the backends that read contacts from an engine (bullet,
// ode, mujoco, dart). When a pair's contact starts is ContactPairTracker's (contact_pair_tracker.h).
#pragma once

#include <map>
#include <utility>

#include "vroc/core/backend.h"

namespace vroc {

/// One contact point after the internal step that solved it.
struct SolvedContact {
    int body_a = -1, body_b = -1;       ///< scene body indices, body_a < body_b
    Vec3 point = Vec3::Zero();          ///< [m] world
    Vec3 normal_a_to_b = Vec3::Zero();  ///< unit, world
    double impulse = 0.0;               ///< [N s] normal impulse in the step; only > 0 counts
};

/// One pair's impulse-carrying points of a step.
struct PairContacts {
    double impulse = 0.0;             ///< [N s] normal impulse of the step, summed over the pair's points
    Vec3 point_sum = Vec3::Zero();    ///< [m] world, over impulse-carrying points
    int point_count = 0;
    Vec3 normal_sum = Vec3::Zero();   ///< impulse-weighted unit normals from a to b, world

    /// One point that carried `impulse` > 0 [N s] along the unit `normal_a_to_b`.
    void addImpulse(const Vec3& point, const Vec3& normal_a_to_b, double impulse);
    /// The collision event at `time` [s]: mean point, impulse-weighted normal, summed impulse.
    /// Needs point_count > 0.
    CollisionEvent event(const std::pair<int, int>& pair, double time) const;
};

/// A step's contacts by pair (a < b), ordered: events come out in a deterministic order.
using StepContacts = std::map<std::pair<int, int>, PairContacts>;

/// The pair key (min, max) of two scene body indices.
inline std::pair<int, int> pairKey(int a, int b) { return a < b ? std::pair{a, b} : std::pair{b, a}; }

}  // namespace vroc
