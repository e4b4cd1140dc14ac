// SPDX-License-Identifier: MIT
#include "event_detection.h"

#include <btBulletCollisionCommon.h>

#include "bullet_convert.h"
#include "vroc/core/contact_events.h"

namespace vroc::bullet {

void EventDetector::afterStep(btDispatcher& dispatcher, double time) {
    StepContacts pairs;
    manifolds_ = static_cast<std::uint64_t>(dispatcher.getNumManifolds());
    points_ = 0;
    for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
        const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
        const int i0 = manifold->getBody0()->getUserIndex();
        const int i1 = manifold->getBody1()->getUserIndex();
        // Bullet's normal on B points from body 1 to body 0; flip to "from a to b".
        const double to_b = i0 < i1 ? -1.0 : 1.0;
        PairContacts& pc = pairs[pairKey(i0, i1)];
        for (int p = 0; p < manifold->getNumContacts(); ++p) {
            const btManifoldPoint& cp = manifold->getContactPoint(p);
            ++points_;
            const double j = cp.getAppliedImpulse();
            if (cp.getDistance() < collision_distance_ || j > 0.0) pc.in_contact = true;
            if (j <= 0.0) continue;
            pc.addImpulse(0.5 * (fromBt(cp.getPositionWorldOnA()) + fromBt(cp.getPositionWorldOnB())),
                          to_b * fromBt(cp.m_normalWorldOnB), j);
        }
    }
    points_total_ += points_;
    std::set<std::pair<int, int>> now;
    for (const auto& [pair, pc] : pairs) {
        if (!pc.in_contact) continue;
        now.insert(pair);
        if (pc.impulse <= 0.0 || in_contact_.count(pair)) continue;
        pending_.push_back(pc.event(pair, time));
        ++events_total_;
    }
    in_contact_ = std::move(now);
}

std::vector<CollisionEvent> EventDetector::take() {
    std::vector<CollisionEvent> out;
    out.swap(pending_);
    return out;
}

}  // namespace vroc::bullet
