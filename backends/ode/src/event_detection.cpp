// SPDX-License-Identifier: MIT
#include "event_detection.h"

#include "vroc/core/contact_events.h"

namespace vroc::ode {

void EventDetector::afterStep(const std::vector<SolvedContact>& solved, const std::set<std::pair<int, int>>& touching,
                              double time) {
    StepContacts pairs;
    for (const SolvedContact& c : solved)
        if (c.impulse > 0.0) pairs[{c.body_a, c.body_b}].addImpulse(c.point, c.normal_a_to_b, c.impulse);
    std::set<std::pair<int, int>> now;
    for (const auto& pair : touching)
        if (in_contact_.count(pair)) now.insert(pair);   // touching keeps a contact, never starts one
    for (const auto& [pair, p] : pairs) {
        now.insert(pair);
        if (in_contact_.count(pair)) continue;
        pending_.push_back(p.event(pair, time));
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
