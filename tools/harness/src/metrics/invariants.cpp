// SPDX-License-Identifier: MIT
#include "vroc/harness/metrics/invariants.h"

namespace vroc::harness {

std::vector<int> virtualBodyIndices(const Scene& scene) {
    std::vector<int> out;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
        if (scene.bodies[i].isDynamic()) out.push_back(static_cast<int>(i));
    return out;
}

Vec3 centerOfMass(const Body& body, const BodyState& state) {
    return state.pose.apply(body.mass_properties.center_of_mass);
}

Invariants computeInvariants(const Scene& scene, std::span<const BodyState> states) {
    Invariants inv;
    for (std::size_t i = 0; i < scene.bodies.size() && i < states.size(); ++i) {
        const Body& body = scene.bodies[i];
        if (!body.isDynamic()) continue;
        const BodyState& s = states[i];
        const double m = body.mass_properties.mass;
        const Mat3 R = s.pose.orientation.normalized().toRotationMatrix();
        const Mat3 inertia_world = R * body.mass_properties.inertia * R.transpose();
        const Vec3 x = centerOfMass(body, s);
        const Vec3 spin = inertia_world * s.angular_velocity;
        inv.kinetic += 0.5 * m * s.linear_velocity.squaredNorm() + 0.5 * s.angular_velocity.dot(spin);
        inv.potential -= m * scene.gravity.dot(x);
        inv.linear_momentum += m * s.linear_velocity;
        inv.angular_momentum += x.cross(m * s.linear_velocity) + spin;
    }
    return inv;
}

}  // namespace vroc::harness
