// SPDX-License-Identifier: MIT
#include "vroc/core/scene.h"

#include <algorithm>
#include <cmath>

namespace vroc {

ContactMaterial combineMaterials(const Material& a, const Material& b) {
    return {std::min(a.restitution, b.restitution), std::sqrt(a.friction * b.friction)};
}

int Scene::findBody(const std::string& body_name) const {
    for (std::size_t i = 0; i < bodies.size(); ++i)
        if (bodies[i].name == body_name) return static_cast<int>(i);
    return -1;
}

std::size_t Scene::virtualBodyCount() const {
    return static_cast<std::size_t>(
        std::count_if(bodies.begin(), bodies.end(), [](const Body& b) { return b.isDynamic(); }));
}

}  // namespace vroc
