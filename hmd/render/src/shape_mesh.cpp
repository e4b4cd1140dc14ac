// SPDX-License-Identifier: MIT
#include "shape_mesh.h"

#include <cmath>
#include <numbers>

namespace vroc::render {
namespace {

void push(std::vector<float>& out, const Vec3& v) {
    out.push_back(static_cast<float>(v.x()));
    out.push_back(static_cast<float>(v.y()));
    out.push_back(static_cast<float>(v.z()));
}

void addPolyhedron(const ConvexPolyhedron& hull, const Pose& pose, ShapeMesh& mesh) {
    for (std::size_t f = 0; f < hull.faces.size(); ++f) {
        const auto& face = hull.faces[f];
        const Vec3 n = pose.rotate(hull.face_normals[f]);
        for (std::size_t i = 1; i + 1 < face.size(); ++i) {   // fan: faces are convex polygons
            for (int v : {face[0], face[i], face[i + 1]}) {
                push(mesh.triangle_positions, pose.apply(hull.vertices[v]));
                push(mesh.triangle_normals, n);
            }
        }
        for (std::size_t i = 0; i < face.size(); ++i) {
            push(mesh.edge_positions, pose.apply(hull.vertices[face[i]]));
            push(mesh.edge_positions, pose.apply(hull.vertices[face[(i + 1) % face.size()]]));
        }
    }
}

Vec3 spherePoint(double theta, double phi) {   // theta from +z, phi about z
    return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

void addSphere(double radius, const Pose& pose, int slices, int stacks, ShapeMesh& mesh) {
    const double pi = std::numbers::pi;
    for (int i = 0; i < stacks; ++i) {
        const double t0 = pi * i / stacks, t1 = pi * (i + 1) / stacks;
        for (int j = 0; j < slices; ++j) {
            const double p0 = 2 * pi * j / slices, p1 = 2 * pi * (j + 1) / slices;
            const Vec3 a = spherePoint(t0, p0), b = spherePoint(t1, p0), c = spherePoint(t1, p1),
                       d = spherePoint(t0, p1);
            for (const Vec3* v : {&a, &b, &c, &a, &c, &d}) {   // smooth normals: the unit radius
                push(mesh.triangle_positions, pose.apply(radius * *v));
                push(mesh.triangle_normals, pose.rotate(*v));
            }
        }
    }
    // Wireframe: the equator and two meridians, enough to show a real sphere's place and spin.
    for (int j = 0; j < slices; ++j) {
        const double p0 = 2 * pi * j / slices, p1 = 2 * pi * (j + 1) / slices;
        push(mesh.edge_positions, pose.apply(radius * spherePoint(pi / 2, p0)));
        push(mesh.edge_positions, pose.apply(radius * spherePoint(pi / 2, p1)));
        for (double phi : {0.0, pi / 2}) {
            push(mesh.edge_positions, pose.apply(radius * Vec3(std::cos(p0) * std::cos(phi), std::cos(p0) * std::sin(phi), std::sin(p0))));
            push(mesh.edge_positions, pose.apply(radius * Vec3(std::cos(p1) * std::cos(phi), std::cos(p1) * std::sin(phi), std::sin(p1))));
        }
    }
}

void addShape(const Shape& shape, const Pose& pose, int slices, int stacks, ShapeMesh& mesh) {
    switch (shape.kind) {
        case Shape::Kind::Sphere: addSphere(shape.radius, pose, slices, stacks, mesh); break;
        case Shape::Kind::Box: addPolyhedron(ConvexPolyhedron::box(shape.half_extents), pose, mesh); break;
        case Shape::Kind::Hull: addPolyhedron(*shape.hull, pose, mesh); break;
        case Shape::Kind::Compound:
            for (const ShapePart& part : shape.parts) addShape(part.shape, pose * part.pose, slices, stacks, mesh);
            break;
    }
}

}  // namespace

ShapeMesh tessellate(const Shape& shape, int slices, int stacks) {
    ShapeMesh mesh;
    addShape(shape, Pose::identity(), slices, stacks, mesh);
    return mesh;
}

}  // namespace vroc::render
