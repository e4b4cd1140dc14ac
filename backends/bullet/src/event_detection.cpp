// SPDX-License-Identifier: MIT
#include "event_detection.h"

#include <set>
#include <utility>

#include <btBulletCollisionCommon.h>

#include "bullet_convert.h"

namespace vroc::bullet {

void EventDetector::afterStep(btDispatcher& dispatcher, double time) {
    std::vector<SolvedContact> solved;
    std::set<std::pair<int, int>> touching;
    manifolds_ = static_cast<std::uint64_t>(dispatcher.getNumManifolds());
    points_ = 0;
    for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
        const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
        const int i0 = manifold->getBody0()->getUserIndex();
        const int i1 = manifold->getBody1()->getUserIndex();
        // Bullet's normal on B points from body 1 to body 0; flip to "from a to b".
        const double to_b = i0 < i1 ? -1.0 : 1.0;
        const auto [a, b] = pairKey(i0, i1);
        for (int p = 0; p < manifold->getNumContacts(); ++p) {
            const btManifoldPoint& cp = manifold->getContactPoint(p);
            ++points_;
            if (cp.getDistance() < collision_distance_) touching.insert({a, b});
            solved.push_back({a, b, 0.5 * (fromBt(cp.getPositionWorldOnA()) + fromBt(cp.getPositionWorldOnB())),
                              to_b * fromBt(cp.m_normalWorldOnB), cp.getAppliedImpulse()});
        }
    }
    points_total_ += points_;
    tracker_.afterStep(solved, touching, time);
}

}  // namespace vroc::bullet
