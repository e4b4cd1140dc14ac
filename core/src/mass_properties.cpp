// SPDX-License-Identifier: MIT
// Volume integrals at unit density. Polyhedra: each face is fanned into triangles, each triangle
// with a reference point inside the hull forms a tetrahedron whose second moment is known in closed
// form (the canonical-tetrahedron covariance, as in Blow & Binstock 2004 / Tonon 2004).
#include "vroc/core/mass_properties.h"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "vroc/core/errors.h"

namespace vroc {
namespace {

/// Inertia tensor about a point from the second moment S = integral of x x^T dV about that point.
Mat3 inertiaFromSecondMoment(const Mat3& s) { return s.trace() * Mat3::Identity() - s; }

MassProperties sphereProperties(double r) {
    MassProperties m;
    m.volume = 4.0 / 3.0 * std::numbers::pi * r * r * r;
    m.inertia = 0.4 * m.volume * r * r * Mat3::Identity();
    return m;
}

MassProperties boxProperties(const Vec3& h) {
    MassProperties m;
    m.volume = 8.0 * h.x() * h.y() * h.z();
    const Vec3 sq = h.cwiseProduct(h);
    m.inertia = (m.volume / 3.0 * Vec3(sq.y() + sq.z(), sq.x() + sq.z(), sq.x() + sq.y())).asDiagonal();
    return m;
}

MassProperties hullProperties(const ConvexPolyhedron& p) {
    MassProperties m;
    if (p.vertices.empty()) return m;
    // Integrate about the vertex mean: keeps the sums well conditioned for hulls far from the origin.
    Vec3 ref = Vec3::Zero();
    for (const Vec3& v : p.vertices) ref += v;
    ref /= static_cast<double>(p.vertices.size());
    double volume = 0.0;
    Vec3 first = Vec3::Zero();    // integral of x dV about ref
    Mat3 second = Mat3::Zero();   // integral of x x^T dV about ref
    for (const auto& face : p.faces) {
        const Vec3 a = p.vertices[face[0]] - ref;
        for (size_t i = 1; i + 1 < face.size(); ++i) {
            const Vec3 b = p.vertices[face[i]] - ref;
            const Vec3 c = p.vertices[face[i + 1]] - ref;
            const double det = a.dot(b.cross(c));   // 6 x signed volume of tetra (ref, a, b, c)
            const Vec3 sum = a + b + c;
            volume += det / 6.0;
            first += det / 24.0 * sum;
            second += det / 120.0 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + sum * sum.transpose());
        }
    }
    m.volume = volume;
    if (!(volume > 0.0)) return m;
    const Vec3 centroid = first / volume;
    m.center_of_mass = ref + centroid;
    m.inertia = inertiaFromSecondMoment(second - volume * centroid * centroid.transpose());
    return m;
}

/// Parts posed in the compound frame: rotate each part's inertia, then parallel-axis to the
/// common centroid.
MassProperties compoundProperties(const std::vector<ShapePart>& parts) {
    MassProperties total;
    std::vector<MassProperties> posed;
    for (const ShapePart& part : parts) {
        MassProperties m = unitDensityProperties(part.shape);
        const Mat3 r = part.pose.orientation.normalized().toRotationMatrix();
        m.center_of_mass = part.pose.apply(m.center_of_mass);
        m.inertia = r * m.inertia * r.transpose();
        total.volume += m.volume;
        total.center_of_mass += m.volume * m.center_of_mass;
        posed.push_back(m);
    }
    if (!(total.volume > 0.0)) return total;
    total.center_of_mass /= total.volume;
    for (const MassProperties& m : posed) {
        const Vec3 d = m.center_of_mass - total.center_of_mass;
        total.inertia += m.inertia + m.volume * (d.squaredNorm() * Mat3::Identity() - d * d.transpose());
    }
    return total;
}

}  // namespace

MassProperties unitDensityProperties(const Shape& shape) {
    MassProperties m;
    switch (shape.kind) {
        case Shape::Kind::Sphere: m = sphereProperties(shape.radius); break;
        case Shape::Kind::Box: m = boxProperties(shape.half_extents); break;
        case Shape::Kind::Hull:
            if (!shape.hull) throw GeometryError("hull shape has no polyhedron");
            m = hullProperties(*shape.hull);
            break;
        case Shape::Kind::Compound: m = compoundProperties(shape.parts); break;
    }
    m.mass = m.volume;   // unit density
    return m;
}

MassProperties massProperties(const Shape& shape, double mass) {
    if (!std::isfinite(mass) || !(mass > 0.0))
        throw InputError(fmt::format("mass must be a positive finite number of kg, got {}", mass));
    MassProperties m = unitDensityProperties(shape);
    if (!std::isfinite(m.volume) || !(m.volume > 0.0))
        throw GeometryError(fmt::format("{} shape has no volume ({} m^3): cannot give it a mass", shape.kindName(), m.volume));
    const double density = mass / m.volume;
    m.mass = mass;
    m.inertia *= density;
    return m;
}

}  // namespace vroc
