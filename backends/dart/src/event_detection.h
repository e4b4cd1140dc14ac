// SPDX-License-Identifier: MIT
// Collision events by the definition in docs/events.md, from what one DART world step gives: the
// contacts its constraint solver found at the step's start (World::getLastCollisionResult), each
// with the force the solver applied (Contact::force, the impulse over the step). DART finds a
// pair touching and acts on it in the same step, so as in the ODE backend a pair is in contact
// after a step if it received a positive normal impulse in it, or it was in contact before and
// the step still found it touching; a collision is a pair with a positive impulse that was not in
// contact after the previous step.
#pragma once

#include <cstdint>
#include <set>
#include <utility>
#include <vector>

#include "vroc/core/backend.h"

namespace vroc::dart {

/// One contact point after the step that solved it.
struct SolvedContact {
    int body_a = -1, body_b = -1;       ///< scene body indices, body_a < body_b
    Vec3 point = Vec3::Zero();          ///< [m] world
    Vec3 normal_a_to_b = Vec3::Zero();  ///< unit, world
    double impulse = 0.0;               ///< [N s] normal impulse in the step (>= 0)
};

class EventDetector {
public:
    /// `solved`: every contact point of the step (touching pairs, with or without impulse).
    void afterStep(const std::vector<SolvedContact>& solved, double time);
    /// Events since the previous call, in time order (then by pair).
    std::vector<CollisionEvent> take();

    std::uint64_t pairsInContact() const { return in_contact_.size(); }  ///< after the last step
    std::uint64_t eventTotal() const { return events_total_; }

private:
    std::set<std::pair<int, int>> in_contact_;
    std::vector<CollisionEvent> pending_;
    std::uint64_t events_total_ = 0;
};

}  // namespace vroc::dart
