// SPDX-License-Identifier: MIT
#include "contact_materials.h"

#include <utility>

namespace vroc::mujoco {

ContactMaterials::ContactMaterials(const Scene& scene, double timeconst, double max_step, bool map_restitution)
    : scene_(scene), timeconst_(timeconst), max_step_(max_step), map_restitution_(map_restitution) {
    std::map<std::pair<double, double>, int> ids;
    for (const Body& body : scene.bodies) {
        const Material& m = scene.materials.at(static_cast<std::size_t>(body.material));
        const auto it = ids.emplace(std::make_pair(m.restitution, m.friction), static_cast<int>(ids.size())).first;
        groups_.push_back(it->second);
    }
}

PairMaterial ContactMaterials::make(double restitution, double friction) const {
    PairMaterial p;
    p.friction = friction;
    p.restitution = restitution;
    p.default_solref = !map_restitution_;
    if (map_restitution_) {
        auto it = springs_.find(restitution);
        if (it == springs_.end()) it = springs_.emplace(restitution, contactSpring(restitution, timeconst_, max_step_)).first;
        p.spring = it->second;
    }
    return p;
}

PairMaterial ContactMaterials::ofBody(int body) const {
    const Material& m = scene_.materials.at(static_cast<std::size_t>(scene_.bodies.at(static_cast<std::size_t>(body)).material));
    return make(m.restitution, m.friction);
}

PairMaterial ContactMaterials::ofPair(int body_a, int body_b) const {
    const Material& a = scene_.materials.at(static_cast<std::size_t>(scene_.bodies.at(static_cast<std::size_t>(body_a)).material));
    const Material& b = scene_.materials.at(static_cast<std::size_t>(scene_.bodies.at(static_cast<std::size_t>(body_b)).material));
    const ContactMaterial c = combineMaterials(a, b);
    return make(c.restitution, c.friction);
}

}  // namespace vroc::mujoco
