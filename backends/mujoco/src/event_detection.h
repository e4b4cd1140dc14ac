// SPDX-License-Identifier: MIT
// Collision events from MuJoCo's contact list (docs/events.md, adapted as below). After mj_step
// the list holds the contacts found at the start of that step (every one closer than the scene's
// collision distance: that is the geoms' margin) and mj_contactForce gives the force the solver
// applied through each during the step: a solved contact with impulse force x step. A pair is
// touching if it has a contact closer than the collision distance or one that carried a positive
// normal force.
// Adaptation (TouchingRule::StartsContactEventAtFirstImpulse): a collision is the first step with a
// positive normal impulse in an unbroken run of steps in contact. MuJoCo's force starts only once
// the surfaces overlap, so a pair often spends a step inside the collision distance with no force
// yet; events.md's literal rule ("not in contact after the previous step") would then drop the
// collision. A resting or sliding contact still gives one event, a new bounce (after the pair left
// contact) a new one. MuJoCo's soft contact spreads a collision over several steps: an event's
// impulse is the first step's share (docs/mujoco-backend.md quotes it).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include <mujoco/mujoco.h>

#include "vroc/core/backend.h"
#include "vroc/core/contact_pair_tracker.h"

namespace vroc::mujoco {

class EventDetector {
public:
    /// `collision_distance` [m]: the scene's largest touching distance. `geom_body`: scene body
    /// index of every MuJoCo geom.
    EventDetector(double collision_distance, std::vector<int> geom_body)
        : collision_distance_(collision_distance), geom_body_(std::move(geom_body)) {}

    /// Scans the contacts after an internal step of `h` [s] that ended at `time` [s].
    void afterStep(const mjModel& m, const mjData& d, double h, double time);
    /// Forgets the contact state (after the state was put back by the recovery).
    void reset() { tracker_.reset(); }
    /// Events since the previous call, in time order (then by pair).
    std::vector<CollisionEvent> take() { return tracker_.take(); }

    std::uint64_t contactPointTotal() const { return points_total_; }           ///< summed over steps
    std::uint64_t pairsInContact() const { return tracker_.pairsInContact(); }  ///< after the last step
    std::uint64_t eventTotal() const { return tracker_.eventTotal(); }

private:
    double collision_distance_;
    std::vector<int> geom_body_;
    ContactPairTracker tracker_{TouchingRule::StartsContactEventAtFirstImpulse};
    std::uint64_t points_total_ = 0;
};

}  // namespace vroc::mujoco
