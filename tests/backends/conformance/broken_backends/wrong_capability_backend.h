// SPDX-License-Identifier: MIT
// Broken on purpose: declares what it does not do. It keeps native's capabilities (hull: exact,
// no note) but collides every hull as its bounding sphere about the body origin (mass properties
// unchanged), a shortcut that a declaration of "approximated: bounding sphere" would have been
// honest about. Rejected by checkLanding: a hull plate dropped flat comes to rest its bounding
// radius above the floor, not on it.
#pragma once

#include <memory>

#include "broken_backends/delegating_backend.h"

namespace vroc::conformance {

/// `shape` with every hull (a body's own or a compound part) replaced by its bounding sphere.
inline Shape hullsAsSpheres(const Shape& shape) {
    if (shape.kind == Shape::Kind::Hull) return Shape::sphere(shape.boundingRadius());
    Shape out = shape;
    for (ShapePart& part : out.parts) part.shape = hullsAsSpheres(part.shape);
    return out;
}

inline BackendInfo wrongCapabilityBackend() {
    return wrappedNativeInfo("wrong_capability",
                             [](const Scene& scene, const Settings& settings) -> std::unique_ptr<Backend> {
                                 Scene spheres = scene;
                                 for (Body& b : spheres.bodies) b.shape = hullsAsSpheres(b.shape);
                                 return std::make_unique<DelegatingBackend>(nativeInfo().create(spheres, settings));
                             });
}

}  // namespace vroc::conformance
