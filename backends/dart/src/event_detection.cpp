// SPDX-License-Identifier: MIT
#include "event_detection.h"

#include "vroc/core/contact_events.h"

namespace vroc::dart {

void EventDetector::afterStep(const std::vector<SolvedContact>& solved, double time) {
    StepContacts pairs;
    std::set<std::pair<int, int>> now;
    for (const SolvedContact& c : solved) {
        const std::pair<int, int> pair{c.body_a, c.body_b};
        if (c.impulse > 0.0)
            pairs[pair].addImpulse(c.point, c.normal_a_to_b, c.impulse);
        else if (in_contact_.count(pair))
            now.insert(pair);  // touching keeps a contact, never starts one
    }
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

}  // namespace vroc::dart
