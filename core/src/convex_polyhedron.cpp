// SPDX-License-Identifier: MIT
#include "vroc/core/convex_polyhedron.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <fmt/format.h>

#include "polyhedron_checks.h"
#include "qhull_runner.h"
#include "vroc/core/errors.h"

namespace vroc {
namespace {

// Tolerances relative to the point cloud's bounding-box diagonal L.
constexpr double kMergeRelative = 1e-9;      // facets this close to coplanar become one face
constexpr double kValidateRelative = 1e-8;   // planarity / convexity check of the result
constexpr double kThinRelative = 1e-8;       // hull thinner than this (3V/A) counts as flat

struct Face {
    std::vector<int> ids;   // vertex indices, CCW seen from outside
    Vec3 normal;            // unit outward
    double offset = 0.0;    // normal.dot(x) == offset on the plane
};

void checkInput(std::span<const Vec3> points) {
    if (points.size() < 4)
        throw GeometryError(fmt::format("convex hull needs at least 4 points, got {}", points.size()));
    for (size_t i = 0; i < points.size(); ++i)
        if (!points[i].allFinite())
            throw GeometryError(fmt::format("convex hull point {} is not finite ({}, {}, {})", i,
                                            points[i].x(), points[i].y(), points[i].z()));
}

/// Vertices on fewer than 3 faces are not corners (interior or mid-edge points): drop them.
void dropNonCorners(std::vector<detail::QhullFacet>& facets, size_t n_points) {
    std::vector<int> degree(n_points, 0);
    for (const auto& f : facets)
        for (int id : f.point_ids) ++degree[id];
    for (auto& f : facets)
        std::erase_if(f.point_ids, [&](int id) { return degree[id] < 3; });
}

/// Sorts a convex face's vertices counter-clockwise about `normal` (i.e. seen from outside).
void orderCounterClockwise(std::vector<int>& ids, const std::vector<Vec3>& pos, const Vec3& normal) {
    Vec3 centre = Vec3::Zero();
    for (int i : ids) centre += pos[i];
    centre /= static_cast<double>(ids.size());
    const Vec3 u = (pos[ids[0]] - centre).normalized();
    const Vec3 w = normal.cross(u);
    auto angle = [&](int i) { return std::atan2((pos[i] - centre).dot(w), (pos[i] - centre).dot(u)); };
    std::vector<std::pair<double, int>> keyed;
    for (int i : ids) keyed.emplace_back(angle(i), i);
    std::sort(keyed.begin(), keyed.end());
    for (size_t k = 0; k < ids.size(); ++k) ids[k] = keyed[k].second;
}

/// Newell's normal of an ordered polygon (robust for slightly non-planar polygons).
Vec3 newellNormal(const std::vector<int>& ids, const std::vector<Vec3>& pos) {
    Vec3 n = Vec3::Zero();
    for (size_t k = 0; k < ids.size(); ++k) n += pos[ids[k]].cross(pos[ids[(k + 1) % ids.size()]]);
    return n.normalized();
}

/// Canonical layout, independent of qhull's facet order: each face starts at its smallest index,
/// faces sorted.
void canonicalise(std::vector<Face>& faces) {
    for (Face& f : faces) std::rotate(f.ids.begin(), std::min_element(f.ids.begin(), f.ids.end()), f.ids.end());
    std::sort(faces.begin(), faces.end(), [](const Face& a, const Face& b) { return a.ids < b.ids; });
}

/// Builds the polyhedron from qhull's facets. `local` are the points shifted to their box centre
/// (better conditioned); the stored vertices are the exact input points.
ConvexPolyhedron assemble(std::vector<detail::QhullFacet> facets, std::span<const Vec3> points,
                          const std::vector<Vec3>& local) {
    dropNonCorners(facets, points.size());
    std::vector<int> remap(points.size(), -1);   // input point id -> vertex index, in input order
    for (const auto& f : facets)
        for (int id : f.point_ids) remap[id] = 0;
    ConvexPolyhedron p;
    std::vector<Vec3> local_vertices;
    for (size_t id = 0; id < points.size(); ++id) {
        if (remap[id] < 0) continue;
        remap[id] = static_cast<int>(p.vertices.size());
        p.vertices.push_back(points[id]);
        local_vertices.push_back(local[id]);
    }
    std::vector<Face> faces;
    for (const auto& f : facets) {
        Face face;
        for (int id : f.point_ids) face.ids.push_back(remap[id]);
        if (face.ids.size() < 3) continue;   // degenerate sliver; validation reports the hole
        orderCounterClockwise(face.ids, local_vertices, f.outward_normal);
        face.normal = newellNormal(face.ids, local_vertices);
        for (int i : face.ids) face.offset += face.normal.dot(p.vertices[i]);
        face.offset /= static_cast<double>(face.ids.size());
        faces.push_back(std::move(face));
    }
    canonicalise(faces);
    for (Face& f : faces) {
        p.faces.push_back(std::move(f.ids));
        p.face_normals.push_back(f.normal);
        p.face_offsets.push_back(f.offset);
    }
    return p;
}

void rejectIfFlat(const ConvexPolyhedron& p, size_t n_points, double extent) {
    const detail::VolumeArea va = detail::volumeAndArea(p);
    const double thickness = va.area > 0.0 ? 3.0 * va.volume / va.area : 0.0;
    if (!(thickness > kThinRelative * extent))
        throw GeometryError(fmt::format(
            "convex hull of {} points is degenerate: nearly flat (mean thickness {:.3g} m for extent {:.3g} m)",
            n_points, thickness, extent));
}

/// Every input point must lie inside every face plane within `tol` (the documented contract).
/// Beyond a work budget this is left to qhull's own guarantee (points within its facets' outer
/// planes), which our re-fitted planes match to within the planarity check.
void checkContainsInput(const ConvexPolyhedron& p, std::span<const Vec3> points, double tol) {
    constexpr double kBudget = 2e7;
    if (static_cast<double>(points.size()) * static_cast<double>(p.faces.size()) > kBudget) return;
    for (size_t f = 0; f < p.faces.size(); ++f)
        for (size_t i = 0; i < points.size(); ++i) {
            const double out = p.face_normals[f].dot(points[i]) - p.face_offsets[f];
            if (out > tol)
                throw GeometryError(fmt::format(
                    "convex hull of {} points is degenerate: input point {} lies {:.3g} m outside face {}",
                    points.size(), i, out, f));
        }
}

}  // namespace

ConvexPolyhedron ConvexPolyhedron::fromPoints(std::span<const Vec3> points) {
    checkInput(points);
    Vec3 lo = points[0], hi = points[0];
    for (const Vec3& q : points) {
        lo = lo.cwiseMin(q);
        hi = hi.cwiseMax(q);
    }
    const double extent = (hi - lo).norm();
    if (!(extent > 0.0))
        throw GeometryError(fmt::format("convex hull of {} points is degenerate: all points coincide", points.size()));
    const Vec3 centre = 0.5 * (lo + hi);
    std::vector<Vec3> local;
    local.reserve(points.size());
    for (const Vec3& q : points) local.push_back(q - centre);

    ConvexPolyhedron p = assemble(detail::runQhull(local, kMergeRelative * extent), points, local);
    rejectIfFlat(p, points.size(), extent);
    const double magnitude = std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff());
    const double tol = kValidateRelative * extent + 64.0 * std::numeric_limits<double>::epsilon() * magnitude;
    if (std::string why = detail::checkPolyhedron(p, tol); !why.empty())
        throw GeometryError(fmt::format("convex hull of {} points is degenerate: {}", points.size(), why));
    checkContainsInput(p, points, tol);
    return p;
}

ConvexPolyhedron ConvexPolyhedron::box(const Vec3& h) {
    ConvexPolyhedron p;
    // Vertex i has sign bits: bit 0 -> x, bit 1 -> y, bit 2 -> z (set = positive).
    for (int i = 0; i < 8; ++i)
        p.vertices.emplace_back((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(), (i & 4) ? h.z() : -h.z());
    p.faces = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    for (int axis = 0; axis < 3; ++axis)
        for (double sign : {-1.0, 1.0}) {
            p.face_normals.push_back(sign * Vec3::Unit(axis));
            p.face_offsets.push_back(h[axis]);
        }
    return p;
}

int ConvexPolyhedron::edgeCount() const {
    std::vector<std::pair<int, int>> edges;
    for (const auto& face : faces)
        for (size_t i = 0; i < face.size(); ++i) {
            int a = face[i], b = face[(i + 1) % face.size()];
            edges.emplace_back(std::min(a, b), std::max(a, b));
        }
    std::sort(edges.begin(), edges.end());
    return static_cast<int>(std::unique(edges.begin(), edges.end()) - edges.begin());
}

double ConvexPolyhedron::boundingRadius() const {
    double r2 = 0.0;
    for (const Vec3& v : vertices) r2 = std::max(r2, v.squaredNorm());
    return std::sqrt(r2);
}

}  // namespace vroc
