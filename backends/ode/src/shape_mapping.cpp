// SPDX-License-Identifier: MIT
#include "shape_mapping.h"

#include <cmath>
#include <cstdint>

#include "ode_convert.h"

namespace vroc::ode {
namespace {

std::string hullProblem(const ConvexPolyhedron& hull) {
    const std::size_t nv = hull.vertices.size();
    if (nv < 4) return "hull has " + std::to_string(nv) + " vertices (a closed polyhedron needs at least 4)";
    if (hull.faces.size() < 4)
        return "hull has " + std::to_string(hull.faces.size()) +
               " faces (ODE's trimesh and convex geoms are built from the face polygons)";
    for (std::size_t f = 0; f < hull.faces.size(); ++f) {
        if (hull.faces[f].size() < 3) return "hull face " + std::to_string(f) + " has fewer than 3 vertices";
        for (int i : hull.faces[f])
            if (i < 0 || static_cast<std::size_t>(i) >= nv)
                return "hull face " + std::to_string(f) + " names vertex " + std::to_string(i) + " of " + std::to_string(nv);
    }
    for (const Vec3& v : hull.vertices)
        if (!v.allFinite()) return "hull has a non-finite vertex";
    return "";
}

std::string convexProblem(const Shape& shape) {
    switch (shape.kind) {
        case Shape::Kind::Sphere:
            return shape.radius > 0.0 && std::isfinite(shape.radius) ? "" : "sphere radius must be a positive number";
        case Shape::Kind::Box:
            return shape.half_extents.allFinite() && shape.half_extents.minCoeff() > 0.0
                       ? ""
                       : "box half extents must be positive numbers";
        case Shape::Kind::Hull: return shape.hull ? hullProblem(*shape.hull) : "hull shape without a polyhedron";
        case Shape::Kind::Compound: return "a compound part is itself a compound (compounds are flattened on load)";
    }
    return "unknown shape kind";
}

// Outward unit normal of a face from its polygon (Newell's method): used when the polyhedron
// carries no face normals (hulls built in code).
Vec3 newellNormal(const std::vector<Vec3>& v, const std::vector<int>& face) {
    Vec3 n = Vec3::Zero();
    for (std::size_t i = 0; i < face.size(); ++i) {
        const Vec3& a = v[static_cast<std::size_t>(face[i])];
        const Vec3& b = v[static_cast<std::size_t>(face[(i + 1) % face.size()])];
        n += Vec3((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()), (a.x() - b.x()) * (a.y() + b.y()));
    }
    return n.normalized();
}

void setData(dGeomID geom, int scene_index) {
    dGeomSetData(geom, reinterpret_cast<void*>(static_cast<std::intptr_t>(scene_index)));
}

bool isIdentity(const Pose& p) {
    return p.position == Vec3::Zero() && p.orientation.w() == 1.0 && p.orientation.vec() == Vec3::Zero();
}

}  // namespace

std::string unsupportedReason(const Shape& shape) {
    if (shape.kind != Shape::Kind::Compound) return convexProblem(shape);
    if (shape.parts.empty()) return "compound without parts";
    for (std::size_t i = 0; i < shape.parts.size(); ++i) {
        const std::string why = convexProblem(shape.parts[i].shape);
        if (!why.empty()) return "compound part " + std::to_string(i) + ": " + why;
        const Pose& p = shape.parts[i].pose;
        if (!p.position.allFinite() || !p.orientation.coeffs().allFinite())
            return "compound part " + std::to_string(i) + ": non-finite pose";
    }
    return "";
}

ShapeMapper::~ShapeMapper() {
    for (const auto& h : hulls_)
        if (h->trimesh) dGeomTriMeshDataDestroy(h->trimesh);
}

dGeomID ShapeMapper::convexGeom(dSpaceID space, const Shape& part, Pose& geom_in_part) {
    geom_in_part = Pose::identity();
    switch (part.kind) {
        case Shape::Kind::Sphere: return dCreateSphere(space, part.radius);
        case Shape::Kind::Box: {
            const Vec3 size = 2.0 * part.half_extents;   // ODE takes side lengths
            return dCreateBox(space, size.x(), size.y(), size.z());
        }
        case Shape::Kind::Hull: break;
        case Shape::Kind::Compound: return nullptr;   // refused by unsupportedReason()
    }
    Vec3 centroid = Vec3::Zero();
    for (const Vec3& v : part.hull->vertices) centroid += v;
    centroid /= static_cast<double>(part.hull->vertices.size());
    geom_in_part.position = centroid;
    return hullGeom(space, *part.hull, centroid);
}

dGeomID ShapeMapper::hullGeom(dSpaceID space, const ConvexPolyhedron& hull, const Vec3& centroid) {
    auto arrays = std::make_unique<HullArrays>();
    HullArrays& a = *arrays;
    for (const Vec3& v : hull.vertices)
        for (int k = 0; k < 3; ++k) a.points.push_back(v[k] - centroid[k]);
    const int vertex_count = static_cast<int>(hull.vertices.size());
    dGeomID geom = nullptr;
    if (hull_geom_ == HullGeom::TriMesh) {
        // Faces are convex polygons: a fan from their first vertex keeps the winding.
        for (const std::vector<int>& face : hull.faces)
            for (std::size_t k = 1; k + 1 < face.size(); ++k)
                a.triangles.insert(a.triangles.end(), {static_cast<dTriIndex>(face[0]), static_cast<dTriIndex>(face[k]),
                                                       static_cast<dTriIndex>(face[k + 1])});
        a.trimesh = dGeomTriMeshDataCreate();
        dGeomTriMeshDataBuildDouble(a.trimesh, a.points.data(), 3 * sizeof(dReal), vertex_count, a.triangles.data(),
                                    static_cast<int>(a.triangles.size()), 3 * sizeof(dTriIndex));
        geom = dCreateTriMesh(space, a.trimesh, nullptr, nullptr, nullptr);
    } else {
        const bool has_normals = hull.face_normals.size() == hull.faces.size();
        for (std::size_t f = 0; f < hull.faces.size(); ++f) {
            const std::vector<int>& face = hull.faces[f];
            const Vec3 n = has_normals ? hull.face_normals[f].normalized() : newellNormal(hull.vertices, face);
            // Offset from the face's own vertices, relative to the centroid (positive: origin inside).
            double d = 0.0;
            for (int i : face) d += n.dot(hull.vertices[static_cast<std::size_t>(i)] - centroid);
            d /= static_cast<double>(face.size());
            a.planes.insert(a.planes.end(), {n.x(), n.y(), n.z(), d});
            a.polygons.push_back(static_cast<unsigned int>(face.size()));
            for (int i : face) a.polygons.push_back(static_cast<unsigned int>(i));
        }
        geom = dCreateConvex(space, a.planes.data(), static_cast<unsigned int>(hull.faces.size()), a.points.data(),
                             static_cast<unsigned int>(vertex_count), a.polygons.data());
    }
    hulls_.push_back(std::move(arrays));
    return geom;
}

template <class Make>
void ShapeMapper::forEachPart(dSpaceID space, const Shape& shape, const Pose& frame, int scene_index, Make make) {
    auto one = [&](const Shape& part, const Pose& part_pose) {
        Pose geom_in_part;
        dGeomID geom = convexGeom(space, part, geom_in_part);
        setData(geom, scene_index);
        make(geom, frame * part_pose * geom_in_part);
    };
    if (shape.kind == Shape::Kind::Compound) {
        for (const ShapePart& part : shape.parts) one(part.shape, part.pose);
    } else {
        one(shape, Pose::identity());
    }
}

void ShapeMapper::attach(dSpaceID space, dBodyID body, const Shape& shape, const Pose& shape_in_body_frame,
                         int scene_index) {
    forEachPart(space, shape, shape_in_body_frame, scene_index, [&](dGeomID geom, const Pose& offset) {
        dGeomSetBody(geom, body);
        if (isIdentity(offset)) return;   // the geom sits at the body frame itself
        dGeomSetOffsetPosition(geom, offset.position.x(), offset.position.y(), offset.position.z());
        dQuaternion q;
        toOde(offset.orientation, q);
        dGeomSetOffsetQuaternion(geom, q);
    });
}

void ShapeMapper::place(dSpaceID space, const Shape& shape, const Pose& shape_in_world, int scene_index) {
    forEachPart(space, shape, shape_in_world, scene_index, [&](dGeomID geom, const Pose& pose) {
        dGeomSetPosition(geom, pose.position.x(), pose.position.y(), pose.position.z());
        dQuaternion q;
        toOde(pose.orientation, q);
        dGeomSetQuaternion(geom, q);
    });
}

}  // namespace vroc::ode
