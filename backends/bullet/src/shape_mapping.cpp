// SPDX-License-Identifier: MIT
#include "shape_mapping.h"

#include <btBulletCollisionCommon.h>

#include <algorithm>

#include "bullet_convert.h"
#include "hull_shrink.h"

namespace vroc::bullet {
namespace {

bool isIdentity(const Pose& p) {
    return p.position == Vec3::Zero() && p.orientation.w() == 1.0 && p.orientation.vec() == Vec3::Zero();
}

}  // namespace

double innerRadius(const Shape& shape) {
    switch (shape.kind) {
        case Shape::Kind::Sphere: return shape.radius;
        case Shape::Kind::Box: return shape.half_extents.minCoeff();
        case Shape::Kind::Hull:
            // Without face planes, a tenth of the bounding radius is a safe guess.
            if (shape.hull->face_normals.empty()) return 0.1 * shape.hull->boundingRadius();
            return 4.0 * safeHullMargin(*shape.hull, shape.hull->boundingRadius());
        case Shape::Kind::Compound: {
            double r = 0.0;
            for (const ShapePart& part : shape.parts) r = std::max(r, innerRadius(part.shape));
            return r;
        }
    }
    return 0.0;
}

ShapeMapper::ShapeMapper(ShapeOptions options) : options_(options) {}
ShapeMapper::~ShapeMapper() = default;

btCollisionShape* ShapeMapper::keep(std::unique_ptr<btCollisionShape> shape) {
    owned_.push_back(std::move(shape));
    return owned_.back().get();
}

btCollisionShape* ShapeMapper::map(const Shape& shape, const Pose& frame) {
    if (shape.kind != Shape::Kind::Compound && isIdentity(frame)) return convex(shape);
    // Children are placed relative to `frame`: child -> frame = frame^-1 * (child -> body).
    auto compound = std::make_unique<btCompoundShape>(/*enableDynamicAabbTree=*/true,
                                                      static_cast<int>(std::max<std::size_t>(1, shape.parts.size())));
    const Pose to_frame = frame.inverse();
    if (shape.kind == Shape::Kind::Compound) {
        for (const ShapePart& part : shape.parts)
            compound->addChildShape(toBt(to_frame * part.pose), convex(part.shape));
    } else {
        compound->addChildShape(toBt(to_frame), convex(shape));
    }
    return keep(std::move(compound));
}

btCollisionShape* ShapeMapper::convex(const Shape& shape) {
    switch (shape.kind) {
        case Shape::Kind::Sphere:
            // The whole sphere is margin: its surface is exact.
            return keep(std::make_unique<btSphereShape>(shape.radius));
        case Shape::Kind::Box: {
            // btBoxShape keeps its outer extents and rounds edges by the margin (inside).
            auto box = std::make_unique<btBoxShape>(toBt(shape.half_extents));
            box->setMargin(std::min(options_.margin, 0.25 * shape.half_extents.minCoeff()));
            return keep(std::move(box));
        }
        case Shape::Kind::Hull: return hull(*shape.hull);
        case Shape::Kind::Compound: break;   // compounds are never nested (shape.h)
    }
    return keep(std::make_unique<btSphereShape>(shape.boundingRadius()));
}

btCollisionShape* ShapeMapper::hull(const ConvexPolyhedron& poly) {
    const bool has_planes = !poly.face_normals.empty() && poly.face_normals.size() == poly.faces.size();
    std::vector<Vec3> points = poly.vertices;
    double margin = options_.margin;
    if (options_.shrink_hulls && has_planes) {
        margin = safeHullMargin(poly, options_.margin);
        std::vector<Vec3> shrunk = shrunkHullVertices(poly, margin);
        if (shrunk.size() >= 4) points = std::move(shrunk);
        else margin = 0.0;   // could not shrink: margin 0 keeps the surface exact
    } else if (options_.shrink_hulls) {
        margin = 0.0;        // no face planes to shrink: margin 0 keeps the surface exact
    }
    auto shape = std::make_unique<btConvexHullShape>();
    for (const Vec3& p : points) shape->addPoint(toBt(p), /*recalculateLocalAabb=*/false);
    shape->recalcLocalAabb();
    shape->setMargin(margin);
    return keep(std::move(shape));
}

}  // namespace vroc::bullet
