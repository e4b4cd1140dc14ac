// SPDX-License-Identifier: MIT
#include "vroc/core/contact_events.h"

namespace vroc {

void PairContacts::addImpulse(const Vec3& point, const Vec3& normal_a_to_b, double j) {
    impulse += j;
    point_sum += point;
    ++point_count;
    normal_sum += j * normal_a_to_b;
}

CollisionEvent PairContacts::event(const std::pair<int, int>& pair, double time) const {
    CollisionEvent e;
    e.time = time;
    e.body_a = pair.first;
    e.body_b = pair.second;
    e.point = point_sum / static_cast<double>(point_count);
    e.normal = normal_sum.normalized();
    e.impulse = impulse;
    return e;
}

}  // namespace vroc
