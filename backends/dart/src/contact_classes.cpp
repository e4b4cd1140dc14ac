// SPDX-License-Identifier: MIT
#include "contact_classes.h"

#include <algorithm>
#include <cmath>

namespace vroc::dart {

MaterialClasses::MaterialClasses(const Scene& scene) {
    for (const Body& body : scene.bodies) {
        const Material& m = scene.materials.at(static_cast<std::size_t>(body.material));
        const auto same = [&](const Material& c) { return c.restitution == m.restitution && c.friction == m.friction; };
        const auto it = std::find_if(classes_.begin(), classes_.end(), same);
        body_class_.push_back(static_cast<int>(it - classes_.begin()));
        if (it == classes_.end()) classes_.push_back(m);
    }
}

double MaterialClasses::friction(int a, int b) const {
    return combineMaterials(classes_[static_cast<std::size_t>(a)], classes_[static_cast<std::size_t>(b)]).friction;
}

double MaterialClasses::restitution(int a, int b) const {
    return std::sqrt(
        combineMaterials(classes_[static_cast<std::size_t>(a)], classes_[static_cast<std::size_t>(b)]).restitution);
}

const NodeTag* ClassFilter::find(const ::dart::dynamics::ShapeFrame* frame) const {
    const auto it = tags_.find(frame);
    return it == tags_.end() ? nullptr : &it->second;
}

bool ClassFilter::ignoresCollision(const ::dart::collision::CollisionObject* a,
                                   const ::dart::collision::CollisionObject* b) const {
    const NodeTag* ta = find(a->getShapeFrame());
    const NodeTag* tb = find(b->getShapeFrame());
    if (!ta || !tb) return true;
    if (ta->body == tb->body || (!ta->dynamic && !tb->dynamic)) return true;
    return ta->partner_class != tb->own_class || tb->partner_class != ta->own_class;
}

}  // namespace vroc::dart
