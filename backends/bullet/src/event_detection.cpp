// SPDX-License-Identifier: MIT
#include "event_detection.h"

#include <btBulletCollisionCommon.h>

#include <map>

#include "bullet_convert.h"

namespace vroc::bullet {
namespace {

// What one pair's manifolds say after a step (a pair of compounds can have several manifolds).
struct PairContact {
    bool in_contact = false;
    double impulse = 0.0;                 // [N s] sum of normal impulses applied in the step
    Vec3 point_sum = Vec3::Zero();        // sum over impulse-carrying points
    int point_count = 0;
    Vec3 normal_sum = Vec3::Zero();       // impulse-weighted, from a to b
};

}  // namespace

void EventDetector::afterStep(btDispatcher& dispatcher, double time) {
    std::map<std::pair<int, int>, PairContact> pairs;   // ordered: deterministic event order
    manifolds_ = static_cast<std::uint64_t>(dispatcher.getNumManifolds());
    points_ = 0;
    for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
        const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
        const int i0 = manifold->getBody0()->getUserIndex();
        const int i1 = manifold->getBody1()->getUserIndex();
        // Bullet's normal on B points from body 1 to body 0; flip to "from a to b".
        const double to_b = i0 < i1 ? -1.0 : 1.0;
        PairContact& pc = pairs[{std::min(i0, i1), std::max(i0, i1)}];
        for (int p = 0; p < manifold->getNumContacts(); ++p) {
            const btManifoldPoint& cp = manifold->getContactPoint(p);
            ++points_;
            const double j = cp.getAppliedImpulse();
            if (cp.getDistance() < collision_distance_ || j > 0.0) pc.in_contact = true;
            if (j <= 0.0) continue;
            pc.impulse += j;
            pc.point_sum += 0.5 * (fromBt(cp.getPositionWorldOnA()) + fromBt(cp.getPositionWorldOnB()));
            ++pc.point_count;
            pc.normal_sum += to_b * j * fromBt(cp.m_normalWorldOnB);
        }
    }
    points_total_ += points_;
    std::set<std::pair<int, int>> now;
    for (const auto& [pair, pc] : pairs) {
        if (!pc.in_contact) continue;
        now.insert(pair);
        if (pc.impulse <= 0.0 || in_contact_.count(pair)) continue;
        CollisionEvent e;
        e.time = time;
        e.body_a = pair.first;
        e.body_b = pair.second;
        e.point = pc.point_sum / pc.point_count;
        e.normal = pc.normal_sum.normalized();
        e.impulse = pc.impulse;
        pending_.push_back(e);
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
