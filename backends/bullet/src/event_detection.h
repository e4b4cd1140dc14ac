// SPDX-License-Identifier: MIT
// Collision events from Bullet's persistent manifolds, by the definition in docs/events.md:
// a pair is "in contact" after an internal step if one of its contact points is closer than the
// scene's collision distance or the solver applied a positive normal impulse to it in that step
// (Bullet's speculative contacts act before the surfaces meet). A collision is a pair in contact
// with a positive normal impulse that was not in contact after the previous internal step.
#pragma once

#include <cstdint>
#include <set>
#include <utility>
#include <vector>

#include "vroc/core/backend.h"

class btDispatcher;

namespace vroc::bullet {

class EventDetector {
public:
    /// `collision_distance` [m]: the scene's largest touching distance.
    explicit EventDetector(double collision_distance) : collision_distance_(collision_distance) {}

    /// Scans every manifold after an internal step that ended at `time` [s]. Collision objects
    /// carry their scene body index as user index.
    void afterStep(btDispatcher& dispatcher, double time);
    /// Events since the previous call, in time order (then by pair).
    std::vector<CollisionEvent> take();

    std::uint64_t manifoldCount() const { return manifolds_; }          ///< after the last step
    std::uint64_t contactPointCount() const { return points_; }         ///< after the last step
    std::uint64_t contactPointTotal() const { return points_total_; }   ///< summed over steps
    std::uint64_t pairsInContact() const { return in_contact_.size(); } ///< after the last step
    std::uint64_t eventTotal() const { return events_total_; }

private:
    double collision_distance_;
    std::set<std::pair<int, int>> in_contact_;   ///< pairs (a < b) in contact after the last step
    std::vector<CollisionEvent> pending_;
    std::uint64_t manifolds_ = 0, points_ = 0, points_total_ = 0, events_total_ = 0;
};

}  // namespace vroc::bullet
