// SPDX-License-Identifier: MIT
#include "vroc/core/body_states.h"

#include <cstring>

namespace vroc {

bool sameStateBits(const BodyState& a, const BodyState& b) {
    return std::memcmp(a.pose.position.data(), b.pose.position.data(), 3 * sizeof(double)) == 0 &&
           std::memcmp(a.pose.orientation.coeffs().data(), b.pose.orientation.coeffs().data(), 4 * sizeof(double)) == 0 &&
           std::memcmp(a.linear_velocity.data(), b.linear_velocity.data(), 3 * sizeof(double)) == 0 &&
           std::memcmp(a.angular_velocity.data(), b.angular_velocity.data(), 3 * sizeof(double)) == 0;
}

void setBodyStates(Backend& backend, const Scene& scene, std::span<const BodyState> states) {
    for (std::size_t i = 0; i < scene.bodies.size() && i < states.size(); ++i) {
        if (scene.bodies[i].isStatic()) continue;
        const int body = static_cast<int>(i);
        if (!sameStateBits(states[i], backend.bodyState(body))) backend.setBodyState(body, states[i]);
    }
}

}  // namespace vroc
