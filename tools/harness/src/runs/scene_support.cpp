// SPDX-License-Identifier: MIT
#include "vroc/harness/runs/scene_support.h"

#include <map>
#include <vector>

namespace vroc::harness {
namespace {

int rank(Support s) { return s == Support::Exact ? 0 : (s == Support::Approximated ? 1 : 2); }

void useShape(const Shape& shape, const BackendCapabilities& c, std::map<std::string, Support>& used) {
    switch (shape.kind) {
        case Shape::Kind::Sphere: used["sphere"] = c.sphere; break;
        case Shape::Kind::Box: used["box"] = c.box; break;
        case Shape::Kind::Hull: used["hull"] = c.hull; break;
        case Shape::Kind::Compound:
            used["compound"] = c.compound;
            for (const ShapePart& part : shape.parts) useShape(part.shape, c, used);
            break;
    }
}

// The worst level over the features used, and each feature at that level with the backend's note.
SceneSupport worstOf(const std::map<std::string, Support>& used, const BackendCapabilities& capabilities) {
    SceneSupport out;
    for (const auto& [feature, level] : used)
        if (rank(level) > rank(out.level)) out.level = level;
    if (out.level == Support::Exact) return out;
    for (const auto& [feature, level] : used) {
        if (level != out.level) continue;
        if (!out.reason.empty()) out.reason += "; ";
        const auto note = capabilities.notes.find(feature);
        out.reason += feature;
        if (out.level == Support::Unsupported) out.reason += " is not supported";
        if (note != capabilities.notes.end()) out.reason += ": " + note->second;
    }
    return out;
}

}  // namespace

SceneSupport sceneSupport(const Scene& scene, const BackendCapabilities& capabilities) {
    std::map<std::string, Support> used;
    for (const Body& body : scene.bodies) {
        useShape(body.shape, capabilities, used);
        if (body.isTracked()) used["tracked"] = capabilities.tracked;
    }
    for (const Material& m : scene.materials)
        if (m.restitution > 0.0) used["restitution"] = capabilities.restitution;
    return worstOf(used, capabilities);
}

SceneSupport exercisedSupport(const Scene& scene, const BackendCapabilities& capabilities,
                              const std::vector<CollisionEvent>& events) {
    std::map<std::string, Support> used;
    for (const Body& body : scene.bodies)
        if (body.isTracked()) used["tracked"] = capabilities.tracked;
    const int n = static_cast<int>(scene.bodies.size());
    std::vector<bool> touched(scene.bodies.size(), false);
    for (const CollisionEvent& e : events) {
        if (e.body_a < 0 || e.body_b < 0 || e.body_a >= n || e.body_b >= n) continue;
        const Body& a = scene.bodies[static_cast<std::size_t>(e.body_a)];
        const Body& b = scene.bodies[static_cast<std::size_t>(e.body_b)];
        touched[static_cast<std::size_t>(e.body_a)] = touched[static_cast<std::size_t>(e.body_b)] = true;
        const ContactMaterial m = combineMaterials(scene.materials.at(static_cast<std::size_t>(a.material)),
                                                   scene.materials.at(static_cast<std::size_t>(b.material)));
        if (m.restitution > 0.0) used["restitution"] = capabilities.restitution;
        if (m.friction > 0.0 && capabilities.friction != FrictionModel::Cone) used["friction"] = Support::Approximated;
    }
    for (std::size_t i = 0; i < touched.size(); ++i)
        if (touched[i]) useShape(scene.bodies[i].shape, capabilities, used);
    return worstOf(used, capabilities);
}

std::string supportText(const SceneSupport& s) {
    if (s.level == Support::Exact) return "exact";
    return std::string(s.level == Support::Approximated ? "approximated: " : "not supported: ") + s.reason;
}

}  // namespace vroc::harness
