// SPDX-License-Identifier: MIT
// When a pair's contact starts and ends, and the collision event it starts (docs/events.md): the
// one state machine of the backends that read contacts from an engine (bullet, ode, mujoco, dart).
// After each internal step a backend hands over the step's solved contacts and the pairs its engine
// finds touching. A pair with a positive normal impulse in the step is in contact; a pair touching
// without one is in contact as the backend's TouchingRule says. A collision event is reported for
// a pair with a positive impulse whose contact has not had one yet: at the event's step the pair's
// impulse-carrying points give the mean point, the impulse-weighted normal and the summed impulse.
#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "vroc/core/backend.h"
#include "vroc/core/contact_events.h"

namespace vroc {

/// What a pair touching without a positive impulse in the step does to its contact.
enum class TouchingRule {
    /// Touching (closer than the collision distance) starts a contact, and a contact started so has
    /// no event: events.md's rule as written (Bullet, whose speculative impulses act before touching).
    StartsContact,
    /// Touching starts a contact whose event is its first step with a positive impulse: the first
    /// impulse of an unbroken run of steps in contact (MuJoCo, whose soft contact's force starts only
    /// once the surfaces overlap, often a step after they came within the collision distance).
    StartsContactEventAtFirstImpulse,
    /// Touching keeps a contact going but never starts one; only a positive impulse does. ODE's
    /// colliders find a pair touching at the end of one step and its solver acts on it in the next;
    /// DART's contact list holds every touching point of the step, with or without an impulse. Were
    /// touching to start a contact there, it would start before the collision's impulse, and the
    /// collision would never be reported.
    KeepsContact,
};

class ContactPairTracker {
public:
    explicit ContactPairTracker(TouchingRule rule) : rule_(rule) {}

    /// After an internal step that ended at `time` [s]. `solved`: the step's contact points (those
    /// with impulse <= 0 carry nothing); `touching`: the pairs (a < b) touching after the step.
    void afterStep(const std::vector<SolvedContact>& solved, const std::set<std::pair<int, int>>& touching,
                   double time);
    /// Forgets every contact (after a backend put its state back, as MuJoCo's recovery does).
    void reset() { in_contact_.clear(); }
    /// Events since the previous call, in time order (then by pair).
    std::vector<CollisionEvent> take();

    std::uint64_t pairsInContact() const { return in_contact_.size(); }  ///< after the last step
    std::uint64_t eventTotal() const { return events_total_; }

private:
    TouchingRule rule_;
    /// Pairs (a < b) in contact after the last step, each with whether its contact is done with its
    /// event (had it, or under StartsContact began without one).
    std::map<std::pair<int, int>, bool> in_contact_;
    std::vector<CollisionEvent> pending_;
    std::uint64_t events_total_ = 0;
};

}  // namespace vroc
