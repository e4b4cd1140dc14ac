// SPDX-License-Identifier: MIT
#include "hull_shrink.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vroc::bullet {
namespace {

Vec3 vertexCentroid(const ConvexPolyhedron& hull) {
    Vec3 c = Vec3::Zero();
    for (const Vec3& v : hull.vertices) c += v;
    return c / static_cast<double>(std::max<std::size_t>(1, hull.vertices.size()));
}

// Faces touching each vertex.
std::vector<std::vector<int>> incidentFaces(const ConvexPolyhedron& hull) {
    std::vector<std::vector<int>> incident(hull.vertices.size());
    for (std::size_t f = 0; f < hull.faces.size(); ++f)
        for (int v : hull.faces[f]) incident[static_cast<std::size_t>(v)].push_back(static_cast<int>(f));
    return incident;
}

bool insideAll(const ConvexPolyhedron& hull, const Vec3& p, double margin, double tol) {
    for (std::size_t f = 0; f < hull.face_normals.size(); ++f)
        if (hull.face_normals[f].dot(p) > hull.face_offsets[f] - margin + tol) return false;
    return true;
}

}  // namespace

double safeHullMargin(const ConvexPolyhedron& hull, double wanted) {
    const Vec3 c = vertexCentroid(hull);
    double inner = std::numeric_limits<double>::infinity();
    for (std::size_t f = 0; f < hull.face_normals.size(); ++f)
        inner = std::min(inner, hull.face_offsets[f] - hull.face_normals[f].dot(c));
    if (!std::isfinite(inner)) return wanted;
    return std::clamp(0.25 * inner, 0.0, wanted);
}

std::vector<Vec3> shrunkHullVertices(const ConvexPolyhedron& hull, double margin) {
    const double tol = 1e-9 * std::max(1.0, hull.boundingRadius());
    const auto incident = incidentFaces(hull);
    std::vector<Vec3> out;
    for (const auto& faces : incident) {
        const std::size_t n = faces.size();
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j)
                for (std::size_t k = j + 1; k < n; ++k) {
                    Mat3 A;
                    Vec3 b;
                    int rows[3] = {faces[i], faces[j], faces[k]};
                    for (int r = 0; r < 3; ++r) {
                        A.row(r) = hull.face_normals[static_cast<std::size_t>(rows[r])].transpose();
                        b[r] = hull.face_offsets[static_cast<std::size_t>(rows[r])] - margin;
                    }
                    if (std::abs(A.determinant()) < 1e-9) continue;   // (nearly) parallel planes
                    const Vec3 p = A.partialPivLu().solve(b);
                    if (p.allFinite() && insideAll(hull, p, margin, tol)) out.push_back(p);
                }
    }
    return out;
}

}  // namespace vroc::bullet
