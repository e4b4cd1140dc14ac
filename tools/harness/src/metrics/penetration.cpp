// SPDX-License-Identifier: MIT
#include "vroc/harness/metrics/penetration.h"

#include <algorithm>
#include <limits>

#include "vroc/harness/metrics/neutral_distance.h"

namespace vroc::harness {
namespace {

bool mayTouch(const Scene& scene, std::span<const BodyState> s, std::size_t i, std::size_t j, double margin) {
    const double reach = scene.bodies[i].shape.boundingRadius() + scene.bodies[j].shape.boundingRadius() + margin;
    return (s[i].pose.position - s[j].pose.position).norm() <= reach;
}

}  // namespace

double maxPenetration(const Scene& scene, std::span<const BodyState> states) {
    double deepest = 0;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
        for (std::size_t j = i + 1; j < scene.bodies.size(); ++j) {
            if (!scene.bodies[i].isDynamic() && !scene.bodies[j].isDynamic()) continue;   // no response between infinite masses
            if (!mayTouch(scene, states, i, j, 0)) continue;
            const double d = bodyDistance(scene, static_cast<int>(i), states[i].pose, static_cast<int>(j), states[j].pose);
            deepest = std::max(deepest, -d);
        }
    return deepest;
}

double closestDistance(const Scene& scene, std::span<const BodyState> states, int body) {
    double best = std::numeric_limits<double>::infinity();
    const auto b = static_cast<std::size_t>(body);
    for (std::size_t j = 0; j < scene.bodies.size(); ++j) {
        if (j == b) continue;
        best = std::min(best, bodyDistance(scene, body, states[b].pose, static_cast<int>(j), states[j].pose));
    }
    return best;
}

}  // namespace vroc::harness
