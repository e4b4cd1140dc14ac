// SPDX-License-Identifier: MIT
#include "backend/body_shape.h"

#include <algorithm>
#include <limits>

namespace vroc::native {
namespace {

void addPart(const Shape& shape, const Pose& local, std::vector<ConvexPart>& parts) {
    ConvexPart p;
    p.local = local;
    switch (shape.kind) {
        case Shape::Kind::Sphere:
            p.is_sphere = true;
            p.radius = shape.radius;
            break;
        case Shape::Kind::Box:
            p.mesh = std::make_shared<const ConvexMesh>(ConvexMesh::box(shape.half_extents));
            break;
        case Shape::Kind::Hull:
            p.mesh = std::make_shared<const ConvexMesh>(ConvexMesh::fromPolyhedron(*shape.hull));
            break;
        case Shape::Kind::Compound:
            for (const ShapePart& sub : shape.parts) addPart(sub.shape, local * sub.pose, parts);
            return;
    }
    // A ball holding the part (centred on its vertices' mean): compound pairs skip part pairs whose
    // balls are far apart, and carried manifolds bound the turn at the contact by it.
    if (p.is_sphere) {
        p.bound_center = local.position;
        p.bound_radius = p.radius;
        p.box_lower = Vec3::Constant(-p.radius);
        p.box_upper = Vec3::Constant(p.radius);
    } else {
        p.box_lower = Vec3::Constant(std::numeric_limits<double>::infinity());
        p.box_upper = -p.box_lower;
        for (int v = 0; v < p.mesh->vertexCount(); ++v) {
            p.box_lower = p.box_lower.cwiseMin(p.mesh->position(v));
            p.box_upper = p.box_upper.cwiseMax(p.mesh->position(v));
        }
        Vec3 sum = Vec3::Zero();
        for (int v = 0; v < p.mesh->vertexCount(); ++v) sum += local.apply(p.mesh->position(v));
        p.bound_center = sum / static_cast<double>(std::max(1, p.mesh->vertexCount()));
        for (int v = 0; v < p.mesh->vertexCount(); ++v)
            p.bound_radius = std::max(p.bound_radius, (local.apply(p.mesh->position(v)) - p.bound_center).norm());
    }
    p.frame_radius = p.bound_center.norm() + p.bound_radius;
    parts.push_back(std::move(p));
}

// [m] The largest ball about `center` (scene body frame) inside the part; 0 if the centre is outside.
double ballInside(const ConvexPart& p, const Vec3& center) {
    const Vec3 c = p.local.applyInverse(center);   // in the part frame
    if (p.is_sphere) return std::max(0.0, p.radius - c.norm());
    double r = std::numeric_limits<double>::infinity();
    for (int f = 0; f < p.mesh->faceCount(); ++f) r = std::min(r, -p.mesh->faceDistance(f, c));
    return std::max(0.0, r);
}

}  // namespace

BodyShape BodyShape::fromScene(const Shape& shape, const Vec3& com) {
    BodyShape s;
    addPart(shape, Pose::identity(), s.parts);
    for (const ConvexPart& p : s.parts) {
        if (p.is_sphere) {
            s.outer_radius = std::max(s.outer_radius, (p.local.position - com).norm() + p.radius);
        } else {
            for (int v = 0; v < p.mesh->vertexCount(); ++v)
                s.outer_radius = std::max(s.outer_radius, (p.local.apply(p.mesh->position(v)) - com).norm());
        }
    }
    if (s.parts.size() == 1) s.inner_radius = ballInside(s.parts.front(), com);
    s.inner_radius = std::min(s.inner_radius, s.outer_radius);
    s.reach_radius = s.inner_radius;
    if (s.parts.size() > 1) {   // each part about its own centre (a ball holding it: a sphere's own)
        s.reach_radius = std::numeric_limits<double>::infinity();
        for (const ConvexPart& p : s.parts) s.reach_radius = std::min(s.reach_radius, ballInside(p, p.bound_center));
        s.reach_radius = std::min(s.reach_radius, s.outer_radius);
    }
    return s;
}

double ConvexPart::gapToBall(const Pose& world, const Vec3& center, double radius) const {
    const Vec3 c = world.applyInverse(center);
    return (c - c.cwiseMax(box_lower).cwiseMin(box_upper)).norm() - radius;
}

SupportPoints ConvexPart::supportPoints(const Pose& world) const {
    SupportPoints s;
    if (is_sphere) {
        s.points.push_back(world.position);
        s.pad = radius;
        return s;
    }
    s.points.reserve(static_cast<std::size_t>(mesh->vertexCount()));
    for (int v = 0; v < mesh->vertexCount(); ++v) s.points.push_back(world.apply(mesh->position(v)));
    return s;
}

Aabb BodyShape::worldAabb(const Pose& frame) const {
    const double inf = std::numeric_limits<double>::infinity();
    Aabb box{Vec3::Constant(inf), Vec3::Constant(-inf)};
    for (const ConvexPart& p : parts) {
        const Pose world = frame * p.local;
        if (p.is_sphere) {
            box.lower = box.lower.cwiseMin(world.position - Vec3::Constant(p.radius));
            box.upper = box.upper.cwiseMax(world.position + Vec3::Constant(p.radius));
            continue;
        }
        for (int v = 0; v < p.mesh->vertexCount(); ++v) {
            const Vec3 x = world.apply(p.mesh->position(v));
            box.lower = box.lower.cwiseMin(x);
            box.upper = box.upper.cwiseMax(x);
        }
    }
    return box;
}

}  // namespace vroc::native
