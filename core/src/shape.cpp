// SPDX-License-Identifier: MIT
#include "vroc/core/shape.h"

#include <algorithm>

namespace vroc {

Shape Shape::sphere(double r) {
    Shape s;
    s.kind = Kind::Sphere;
    s.radius = r;
    return s;
}

Shape Shape::box(const Vec3& half) {
    Shape s;
    s.kind = Kind::Box;
    s.half_extents = half;
    return s;
}

Shape Shape::convexHull(ConvexPolyhedron hull) {
    Shape s;
    s.kind = Kind::Hull;
    s.hull = std::make_shared<const ConvexPolyhedron>(std::move(hull));
    return s;
}

Shape Shape::compound(std::vector<ShapePart> parts) {
    Shape s;
    s.kind = Kind::Compound;
    s.parts = std::move(parts);
    return s;
}

const char* Shape::kindName() const {
    switch (kind) {
        case Kind::Sphere: return "sphere";
        case Kind::Box: return "box";
        case Kind::Hull: return "hull";
        case Kind::Compound: return "compound";
    }
    return "?";
}

double Shape::boundingRadius() const {
    switch (kind) {
        case Kind::Sphere: return radius;
        case Kind::Box: return half_extents.norm();
        case Kind::Hull: return hull ? hull->boundingRadius() : 0.0;
        case Kind::Compound: {
            double r = 0.0;
            for (const auto& p : parts) r = std::max(r, p.pose.position.norm() + p.shape.boundingRadius());
            return r;
        }
    }
    return 0.0;
}

}  // namespace vroc
