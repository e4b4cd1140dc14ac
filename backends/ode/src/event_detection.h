// SPDX-License-Identifier: MIT
// Collision events by the definition in docs/events.md, from what one internal ODE step gives:
//  - the contact joints of the step, each with its normal impulse (dJointFeedback force on the
//    joint's first body, along the normal, times the step);
//  - the pairs ODE's colliders find touching or overlapping at the end of the step.
// ODE finds a pair touching at the end of one step and acts on it in the next, so touching alone
// cannot start a contact here (every collision would then begin "in contact" and never be
// reported). A pair is in contact after a step if it received a positive normal impulse in the
// step, or it was in contact before and is still touching at the step's end (a resting pair whose
// impulse drops to zero for a step stays in contact). A collision is a pair with a positive impulse
// that was not in contact after the previous step. ODE's colliders see no gap: a pair closer than
// the scene's collision distance but not touching does not keep a contact.
#pragma once

#include <cstdint>
#include <set>
#include <utility>
#include <vector>

#include "vroc/core/backend.h"

namespace vroc::ode {

/// One contact joint after the step that solved it.
struct SolvedContact {
    int body_a = -1, body_b = -1;        ///< scene body indices, body_a < body_b
    Vec3 point = Vec3::Zero();           ///< [m] world
    Vec3 normal_a_to_b = Vec3::Zero();   ///< unit, world
    double impulse = 0.0;                ///< [N s] normal impulse in the step (>= 0)
};

class EventDetector {
public:
    /// `solved`: the step's contact joints; `touching`: pairs (a < b) touching at the step's end.
    void afterStep(const std::vector<SolvedContact>& solved, const std::set<std::pair<int, int>>& touching,
                   double time);
    /// Events since the previous call, in time order (then by pair).
    std::vector<CollisionEvent> take();

    std::uint64_t pairsInContact() const { return in_contact_.size(); }   ///< after the last step
    std::uint64_t eventTotal() const { return events_total_; }

private:
    std::set<std::pair<int, int>> in_contact_;
    std::vector<CollisionEvent> pending_;
    std::uint64_t events_total_ = 0;
};

}  // namespace vroc::ode
