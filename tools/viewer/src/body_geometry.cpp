// SPDX-License-Identifier: MIT
#include "body_geometry.h"

namespace vroc::viewer {
namespace {

ViewerPart convexPart(const Shape& shape, const Pose& pose) {
    ViewerPart part;
    part.pose = pose;
    switch (shape.kind) {
        case Shape::Kind::Sphere:
            part.kind = ViewerPart::Kind::Sphere;
            part.radius = shape.radius;
            break;
        case Shape::Kind::Box:
            part.kind = ViewerPart::Kind::Box;
            part.half_extents = shape.half_extents;
            break;
        case Shape::Kind::Hull:
        case Shape::Kind::Compound:  // never nested (shape.h); kept exhaustive for the compiler
            part.kind = ViewerPart::Kind::Hull;
            if (shape.hull) {
                part.vertices = shape.hull->vertices;
                part.faces = shape.hull->faces;
            }
            break;
    }
    return part;
}

}  // namespace

std::vector<ViewerBody> viewerBodies(const Scene& scene) {
    std::vector<ViewerBody> out;
    int moving = 0;
    for (const Body& body : scene.bodies) {
        ViewerBody v;
        v.name = body.name;
        v.role = body.role;
        v.initial_pose = body.pose;
        v.moving_index = body.isStatic() ? -1 : moving++;
        if (body.shape.kind == Shape::Kind::Compound) {
            for (const ShapePart& p : body.shape.parts) v.parts.push_back(convexPart(p.shape, p.pose));
        } else {
            v.parts.push_back(convexPart(body.shape, Pose::identity()));
        }
        out.push_back(std::move(v));
    }
    return out;
}

}  // namespace vroc::viewer
