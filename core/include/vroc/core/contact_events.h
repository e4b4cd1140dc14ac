// SPDX-License-Identifier: MIT
// What one pair's contact points say after an internal step, and the collision event they make
// (docs/events.md): shared by the backends that read contacts from an engine (bullet, ode,
// mujoco). When a pair starts or continues a contact is each backend's own rule.
#pragma once

#include <map>
#include <utility>

#include "vroc/core/backend.h"

namespace vroc {

struct PairContacts {
    bool in_contact = false;          ///< a point within the collision distance, or one carrying impulse
    double impulse = 0.0;             ///< [N s] normal impulse of the step, summed over the pair's points
    Vec3 point_sum = Vec3::Zero();    ///< [m] world, over impulse-carrying points
    int point_count = 0;
    Vec3 normal_sum = Vec3::Zero();   ///< impulse-weighted unit normals from a to b, world

    /// One point that carried `impulse` > 0 [N s] along the unit `normal_a_to_b`; also marks contact.
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
