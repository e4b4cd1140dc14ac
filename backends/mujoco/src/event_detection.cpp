// SPDX-License-Identifier: MIT
#include "event_detection.h"

#include <map>

#include "vroc/core/contact_events.h"

namespace vroc::mujoco {

void EventDetector::afterStep(const mjModel& m, const mjData& d, double h, double time) {
    StepContacts pairs;
    points_total_ += static_cast<std::uint64_t>(d.ncon);
    for (int i = 0; i < d.ncon; ++i) {
        const mjContact& c = d.contact[i];
        const int b1 = geom_body_[static_cast<std::size_t>(c.geom1)];
        const int b2 = geom_body_[static_cast<std::size_t>(c.geom2)];
        if (b1 == b2) continue;
        // MuJoCo's contact normal (frame row 0) points from geom1 to geom2; flip to "from a to b".
        const double to_b = b1 < b2 ? 1.0 : -1.0;
        PairContacts& pc = pairs[pairKey(b1, b2)];
        double force = 0.0;
        if (c.efc_address >= 0) {
            mjtNum f[6];
            mj_contactForce(&m, &d, i, f);
            force = f[0];
        }
        if (c.dist < collision_distance_ || force > 0.0) pc.in_contact = true;
        if (force <= 0.0) continue;
        pc.addImpulse(Vec3(c.pos[0], c.pos[1], c.pos[2]), to_b * Vec3(c.frame[0], c.frame[1], c.frame[2]), force * h);
    }
    std::map<std::pair<int, int>, bool> now;
    for (const auto& [pair, pc] : pairs) {
        if (!pc.in_contact) continue;
        const auto previous = in_contact_.find(pair);
        bool had_event = previous != in_contact_.end() && previous->second;
        if (!had_event && pc.impulse > 0.0) {
            pending_.push_back(pc.event(pair, time));
            ++events_total_;
            had_event = true;
        }
        now[pair] = had_event;
    }
    in_contact_ = std::move(now);
}

std::vector<CollisionEvent> EventDetector::take() {
    std::vector<CollisionEvent> out;
    out.swap(pending_);
    return out;
}

}  // namespace vroc::mujoco
