// SPDX-License-Identifier: MIT
#include "world_polytope.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace vroc::harness {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

void boxTopology(const Vec3& h, std::vector<Vec3>& v, std::vector<std::vector<int>>& faces) {
    v.clear();
    for (int i = 0; i < 8; ++i)
        v.emplace_back((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(), (i & 4) ? h.z() : -h.z());
    // Counter-clockwise seen from outside: -x, +x, -y, +y, -z, +z.
    faces = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
}

void finish(WorldPolytope& p) {
    std::set<std::pair<int, int>> seen;
    p.normals.clear();
    p.offsets.clear();
    for (const auto& f : p.faces) {
        // Newell's normal: robust for any planar polygon.
        Vec3 n = Vec3::Zero();
        for (std::size_t i = 0; i < f.size(); ++i) {
            const Vec3& a = p.vertices[static_cast<std::size_t>(f[i])];
            const Vec3& b = p.vertices[static_cast<std::size_t>(f[(i + 1) % f.size()])];
            n += a.cross(b);
        }
        n.normalize();
        p.normals.push_back(n);
        p.offsets.push_back(n.dot(p.vertices[static_cast<std::size_t>(f[0])]));
        for (std::size_t i = 0; i < f.size(); ++i) {
            int a = f[i], b = f[(i + 1) % f.size()];
            if (seen.insert({std::min(a, b), std::max(a, b)}).second) p.edges.emplace_back(std::min(a, b), std::max(a, b));
        }
    }
}

double pointSegmentDistance(const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 ab = b - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (a + t * ab - p).norm();
}

// Projection interval of the vertices on an axis.
std::pair<double, double> project(const WorldPolytope& p, const Vec3& axis) {
    double lo = kInf, hi = -kInf;
    for (const Vec3& v : p.vertices) {
        const double s = v.dot(axis);
        lo = std::min(lo, s);
        hi = std::max(hi, s);
    }
    return {lo, hi};
}

}  // namespace

WorldPolytope placePolytope(const Shape& shape, const Pose& pose) {
    WorldPolytope p;
    std::vector<Vec3> local;
    if (shape.kind == Shape::Kind::Box) {
        boxTopology(shape.half_extents, local, p.faces);
    } else {
        local = shape.hull->vertices;
        p.faces = shape.hull->faces;
    }
    for (const Vec3& v : local) p.vertices.push_back(pose.apply(v));
    finish(p);
    return p;
}

double pointFaceDistance(const Vec3& p, const WorldPolytope& poly, std::size_t f) {
    const auto& face = poly.faces[f];
    const Vec3& n = poly.normals[f];
    bool inside = true;
    for (std::size_t i = 0; i < face.size() && inside; ++i) {
        const Vec3& a = poly.vertices[static_cast<std::size_t>(face[i])];
        const Vec3& b = poly.vertices[static_cast<std::size_t>(face[(i + 1) % face.size()])];
        inside = (b - a).cross(p - a).dot(n) >= 0;
    }
    if (inside) return std::abs(n.dot(p) - poly.offsets[f]);
    double best = kInf;
    for (std::size_t i = 0; i < face.size(); ++i)
        best = std::min(best, pointSegmentDistance(p, poly.vertices[static_cast<std::size_t>(face[i])],
                                                   poly.vertices[static_cast<std::size_t>(face[(i + 1) % face.size()])]));
    return best;
}

double pointPolytopeDistance(const Vec3& p, const WorldPolytope& poly) {
    double worst = -kInf;
    for (std::size_t f = 0; f < poly.faces.size(); ++f) worst = std::max(worst, poly.normals[f].dot(p) - poly.offsets[f]);
    if (worst <= 0) return worst;   // inside: minus the distance to the nearest face plane
    double best = kInf;
    for (std::size_t f = 0; f < poly.faces.size(); ++f) best = std::min(best, pointFaceDistance(p, poly, f));
    return best;
}

double segmentDistance(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
    // Closest points of two segments (Ericson, Real-Time Collision Detection 5.1.9), with the
    // endpoint distances as a fallback for parallel segments.
    const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
    const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
    double s = 0, t = 0;
    if (a <= 1e-300 && e <= 1e-300) return r.norm();
    if (a <= 1e-300) {
        t = std::clamp(f / e, 0.0, 1.0);
    } else {
        const double c = d1.dot(r);
        if (e <= 1e-300) {
            s = std::clamp(-c / a, 0.0, 1.0);
        } else {
            const double b = d1.dot(d2), denom = a * e - b * b;
            s = denom > 1e-14 * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
            t = (b * s + f) / e;
            if (t < 0) {
                t = 0;
                s = std::clamp(-c / a, 0.0, 1.0);
            } else if (t > 1) {
                t = 1;
                s = std::clamp((b - c) / a, 0.0, 1.0);
            }
        }
    }
    double best = (p0 + s * d1 - (q0 + t * d2)).norm();
    best = std::min({best, pointSegmentDistance(p0, q0, q1), pointSegmentDistance(p1, q0, q1),
                     pointSegmentDistance(q0, p0, p1), pointSegmentDistance(q1, p0, p1)});
    return best;
}

double polytopeDistance(const WorldPolytope& a, const WorldPolytope& b) {
    // Separating-axis test over face normals and edge-pair crosses; the smallest overlap is the
    // penetration depth when no axis separates (exact for convex polytopes).
    std::vector<Vec3> axes = a.normals;
    axes.insert(axes.end(), b.normals.begin(), b.normals.end());
    for (const auto& ea : a.edges)
        for (const auto& eb : b.edges) {
            Vec3 c = (a.vertices[static_cast<std::size_t>(ea.second)] - a.vertices[static_cast<std::size_t>(ea.first)])
                         .cross(b.vertices[static_cast<std::size_t>(eb.second)] - b.vertices[static_cast<std::size_t>(eb.first)]);
            const double n = c.norm();
            if (n > 1e-12) axes.push_back(c / n);
        }
    double depth = kInf;
    bool separated = false;
    for (const Vec3& axis : axes) {
        const auto [alo, ahi] = project(a, axis);
        const auto [blo, bhi] = project(b, axis);
        const double overlap = std::min(ahi - blo, bhi - alo);
        if (overlap < 0) {
            separated = true;
            break;
        }
        depth = std::min(depth, overlap);
    }
    if (!separated) return -depth;
    // Disjoint: the closest points lie on a vertex-face or an edge-edge pair.
    double best = kInf;
    for (const Vec3& v : a.vertices)
        for (std::size_t f = 0; f < b.faces.size(); ++f) best = std::min(best, pointFaceDistance(v, b, f));
    for (const Vec3& v : b.vertices)
        for (std::size_t f = 0; f < a.faces.size(); ++f) best = std::min(best, pointFaceDistance(v, a, f));
    for (const auto& ea : a.edges)
        for (const auto& eb : b.edges)
            best = std::min(best, segmentDistance(a.vertices[static_cast<std::size_t>(ea.first)], a.vertices[static_cast<std::size_t>(ea.second)],
                                                  b.vertices[static_cast<std::size_t>(eb.first)], b.vertices[static_cast<std::size_t>(eb.second)]));
    return best;
}

}  // namespace vroc::harness
