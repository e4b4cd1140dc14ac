// SPDX-License-Identifier: MIT
#include "event_detection.h"

#include <map>

namespace vroc::ode {
namespace {

struct PairImpulse {
    double impulse = 0.0;             // [N s] summed over the pair's points
    Vec3 point_sum = Vec3::Zero();    // over impulse-carrying points
    int point_count = 0;
    Vec3 normal_sum = Vec3::Zero();   // impulse-weighted, from a to b
};

}  // namespace

void EventDetector::afterStep(const std::vector<SolvedContact>& solved, const std::set<std::pair<int, int>>& touching,
                              double time) {
    std::map<std::pair<int, int>, PairImpulse> pairs;   // ordered: deterministic event order
    for (const SolvedContact& c : solved) {
        if (!(c.impulse > 0.0)) continue;
        PairImpulse& p = pairs[{c.body_a, c.body_b}];
        p.impulse += c.impulse;
        p.point_sum += c.point;
        ++p.point_count;
        p.normal_sum += c.impulse * c.normal_a_to_b;
    }
    std::set<std::pair<int, int>> now;
    for (const auto& pair : touching)
        if (in_contact_.count(pair)) now.insert(pair);   // touching keeps a contact, never starts one
    for (const auto& [pair, p] : pairs) {
        now.insert(pair);
        if (in_contact_.count(pair)) continue;
        CollisionEvent e;
        e.time = time;
        e.body_a = pair.first;
        e.body_b = pair.second;
        e.point = p.point_sum / p.point_count;
        e.normal = p.normal_sum.normalized();
        e.impulse = p.impulse;
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

}  // namespace vroc::ode
