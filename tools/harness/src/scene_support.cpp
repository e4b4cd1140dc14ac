// SPDX-License-Identifier: MIT
#include "vroc/harness/scene_support.h"

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

}  // namespace

SceneSupport sceneSupport(const Scene& scene, const BackendCapabilities& capabilities) {
    std::map<std::string, Support> used;
    for (const Body& body : scene.bodies) {
        useShape(body.shape, capabilities, used);
        if (body.isTracked()) used["tracked"] = capabilities.tracked;
    }
    for (const Material& m : scene.materials)
        if (m.restitution > 0.0) used["restitution"] = capabilities.restitution;
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

std::string supportText(const SceneSupport& s) {
    if (s.level == Support::Exact) return "exact";
    return std::string(s.level == Support::Approximated ? "approximated: " : "not supported: ") + s.reason;
}

}  // namespace vroc::harness
