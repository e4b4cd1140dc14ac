// SPDX-License-Identifier: MIT
#include "event_detection.h"

#include <algorithm>
#include <map>

namespace vroc::mujoco {
namespace {

struct PairContact {
    bool in_contact = false;
    double impulse = 0.0;             // [N s] sum of normal force x step over the pair's contacts
    Vec3 point_sum = Vec3::Zero();    // over contacts that carried force
    int point_count = 0;
    Vec3 normal_sum = Vec3::Zero();   // impulse-weighted, from a to b
};

}  // namespace

void EventDetector::afterStep(const mjModel& m, const mjData& d, double h, double time) {
    std::map<std::pair<int, int>, PairContact> pairs;   // ordered: deterministic event order
    points_total_ += static_cast<std::uint64_t>(d.ncon);
    for (int i = 0; i < d.ncon; ++i) {
        const mjContact& c = d.contact[i];
        const int b1 = geom_body_[static_cast<std::size_t>(c.geom1)];
        const int b2 = geom_body_[static_cast<std::size_t>(c.geom2)];
        if (b1 == b2) continue;
        // MuJoCo's contact normal (frame row 0) points from geom1 to geom2; flip to "from a to b".
        const double to_b = b1 < b2 ? 1.0 : -1.0;
        PairContact& pc = pairs[{std::min(b1, b2), std::max(b1, b2)}];
        double force = 0.0;
        if (c.efc_address >= 0) {
            mjtNum f[6];
            mj_contactForce(&m, &d, i, f);
            force = f[0];
        }
        if (c.dist < collision_distance_ || force > 0.0) pc.in_contact = true;
        if (force <= 0.0) continue;
        pc.impulse += force * h;
        pc.point_sum += Vec3(c.pos[0], c.pos[1], c.pos[2]);
        ++pc.point_count;
        pc.normal_sum += to_b * force * h * Vec3(c.frame[0], c.frame[1], c.frame[2]);
    }
    std::map<std::pair<int, int>, bool> now;
    for (const auto& [pair, pc] : pairs) {
        if (!pc.in_contact) continue;
        const auto previous = in_contact_.find(pair);
        bool had_event = previous != in_contact_.end() && previous->second;
        if (!had_event && pc.impulse > 0.0) {
            CollisionEvent e;
            e.time = time;
            e.body_a = pair.first;
            e.body_b = pair.second;
            e.point = pc.point_sum / pc.point_count;
            e.normal = pc.normal_sum.normalized();
            e.impulse = pc.impulse;
            pending_.push_back(e);
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
