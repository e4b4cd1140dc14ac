// SPDX-License-Identifier: MIT
#include "vroc/core/contact_pair_tracker.h"

namespace vroc {

void ContactPairTracker::afterStep(const std::vector<SolvedContact>& solved,
                                   const std::set<std::pair<int, int>>& touching, double time) {
    StepContacts impulses;
    for (const SolvedContact& c : solved)
        if (c.impulse > 0.0) impulses[{c.body_a, c.body_b}].addImpulse(c.point, c.normal_a_to_b, c.impulse);
    std::map<std::pair<int, int>, bool> now;
    for (const auto& pair : touching) {  // touching without an impulse
        if (impulses.count(pair)) continue;
        const auto before = in_contact_.find(pair);
        if (before != in_contact_.end())
            now[pair] = before->second;
        else if (rule_ != TouchingRule::KeepsContact)
            now[pair] = rule_ == TouchingRule::StartsContact;
    }
    for (const auto& [pair, p] : impulses) {  // a positive impulse: an event unless the contact had one
        const auto before = in_contact_.find(pair);
        if (before == in_contact_.end() || !before->second) {
            pending_.push_back(p.event(pair, time));
            ++events_total_;
        }
        now[pair] = true;
    }
    in_contact_ = std::move(now);
}

std::vector<CollisionEvent> ContactPairTracker::take() {
    std::vector<CollisionEvent> out;
    out.swap(pending_);
    return out;
}

}  // namespace vroc
