// SPDX-License-Identifier: MIT
// Collision events from Bullet's persistent manifolds (docs/events.md): every manifold point of an
// internal step is a solved contact with its applied impulse, and a point closer than the scene's
// collision distance makes its pair touching. Touching starts a contact (TouchingRule::StartsContact):
// Bullet's speculative contacts act before the surfaces meet, so an impulse may come without touching
// but touching never comes before the impulse of a collision. A pair may own several manifolds
// (compounds); core's ContactPairTracker merges them per pair.
#pragma once

#include <cstdint>
#include <vector>

#include "vroc/core/backend.h"
#include "vroc/core/contact_pair_tracker.h"

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
    std::vector<CollisionEvent> take() { return tracker_.take(); }

    std::uint64_t manifoldCount() const { return manifolds_; }                  ///< after the last step
    std::uint64_t contactPointCount() const { return points_; }                 ///< after the last step
    std::uint64_t contactPointTotal() const { return points_total_; }           ///< summed over steps
    std::uint64_t pairsInContact() const { return tracker_.pairsInContact(); }  ///< after the last step
    std::uint64_t eventTotal() const { return tracker_.eventTotal(); }

private:
    double collision_distance_;
    ContactPairTracker tracker_{TouchingRule::StartsContact};
    std::uint64_t manifolds_ = 0, points_ = 0, points_total_ = 0;
};

}  // namespace vroc::bullet
