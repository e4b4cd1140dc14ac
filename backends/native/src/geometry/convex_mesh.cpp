// SPDX-License-Identifier: MIT
#include "geometry/convex_mesh.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include <fmt/format.h>

#include "vroc/core/errors.h"

namespace vroc::native {
namespace {

std::string vecText(const Vec3& v) { return fmt::format("({:.17g}, {:.17g}, {:.17g})", v.x(), v.y(), v.z()); }

[[noreturn]] void fail(const std::string& what) { throw GeometryError("convex mesh: " + what); }

}  // namespace

ConvexMesh ConvexMesh::fromPolyhedron(const ConvexPolyhedron& poly) {
    ConvexMesh mesh;
    mesh.build(poly);
    mesh.computePlanes();
    mesh.validate();
    return mesh;
}

ConvexMesh ConvexMesh::box(const Vec3& half_extents) {
    return fromPolyhedron(ConvexPolyhedron::box(half_extents));
}

// Half-edge slots: undirected edge k owns 2k (smaller -> larger vertex index) and 2k + 1.
void ConvexMesh::build(const ConvexPolyhedron& poly) {
    const int nv = static_cast<int>(poly.vertices.size());
    const int nf = static_cast<int>(poly.faces.size());
    if (nv < 4 || nf < 4) fail(fmt::format("needs >= 4 vertices and faces, got {} and {}", nv, nf));
    if (poly.face_normals.size() != poly.faces.size() || poly.face_offsets.size() != poly.faces.size())
        fail("face_normals / face_offsets do not match faces");
    positions_ = poly.vertices;
    std::map<std::pair<int, int>, int> edge_id;
    for (const auto& f : poly.faces) {
        if (f.size() < 3) fail(fmt::format("a face has {} vertices (need >= 3)", f.size()));
        for (size_t k = 0; k < f.size(); ++k) {
            const int u = f[k], w = f[(k + 1) % f.size()];
            if (u < 0 || u >= nv || w < 0 || w >= nv || u == w) fail("face vertex index out of range or repeated");
            edge_id.try_emplace({std::min(u, w), std::max(u, w)}, static_cast<int>(edge_id.size()));
        }
    }
    const int nh = 2 * static_cast<int>(edge_id.size());
    he_origin_.assign(nh, -1);
    he_next_.assign(nh, -1);
    he_face_.assign(nh, -1);
    vertex_edge_.assign(nv, -1);
    auto slot = [&](int u, int w) { return 2 * edge_id.at({std::min(u, w), std::max(u, w)}) + (u < w ? 0 : 1); };
    for (int fi = 0; fi < nf; ++fi) {
        const auto& f = poly.faces[fi];
        const int n = static_cast<int>(f.size());
        face_edge_.push_back(slot(f[0], f[1]));
        face_size_.push_back(n);
        face_normal_.push_back(poly.face_normals[fi]);
        face_offset_.push_back(poly.face_offsets[fi]);
        for (int k = 0; k < n; ++k) {
            const int h = slot(f[k], f[(k + 1) % n]);
            if (he_face_[h] != -1) fail(fmt::format("edge {}-{} is used twice in the same direction (inconsistent orientation or non-manifold)", f[k], f[(k + 1) % n]));
            he_origin_[h] = f[k];
            he_face_[h] = fi;
            he_next_[h] = slot(f[(k + 1) % n], f[(k + 2) % n]);
            vertex_edge_[f[k]] = h;
        }
    }
    for (int h = 0; h < nh; ++h)
        if (he_face_[h] == -1) fail(fmt::format("not closed: edge {}-{} has one face only", he_origin_[h ^ 1], he_origin_[h ^ 1] == -1 ? -1 : he_next_[h ^ 1] >= 0 ? he_origin_[he_next_[h ^ 1]] : -1));
}

void ConvexMesh::computePlanes() {
    const int nh = halfEdgeCount();
    he_dir_.resize(nh);
    he_side_.resize(nh);
    he_length_.resize(nh);
    for (int h = 0; h < nh; ++h) {
        const Vec3 d = position(destination(h)) - position(origin(h));
        he_length_[h] = d.norm();
        he_dir_[h] = d / he_length_[h];
        he_side_[h] = he_dir_[h].cross(face_normal_[face(h)]).normalized();
    }
    centroid_.setZero();
    Vec3 lo = positions_[0], hi = positions_[0];
    for (const Vec3& p : positions_) {
        centroid_ += p;
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    centroid_ /= vertexCount();
    bounding_radius_ = 0.0;
    for (const Vec3& p : positions_) bounding_radius_ = std::max(bounding_radius_, (p - centroid_).norm());
    scale_ = (hi - lo).norm();
}

// Each check names the feature so a bad input can be found; tolerances are relative to scale_.
void ConvexMesh::validate() const {
    const double tol = 1e-8 * scale_;
    if (vertexCount() - edgeCount() + faceCount() != 2)
        fail(fmt::format("Euler characteristic V-E+F = {}-{}+{} != 2", vertexCount(), edgeCount(), faceCount()));
    for (int v = 0; v < vertexCount(); ++v) {
        if (!positions_[v].allFinite()) fail(fmt::format("vertex {} is not finite", v));
        if (vertex_edge_[v] < 0) fail(fmt::format("vertex {} is on no face", v));
    }
    int ring_total = 0;
    for (int v = 0; v < vertexCount(); ++v) {
        Vec3 normal_sum = Vec3::Zero();
        int h = vertex_edge_[v], degree = 0;
        do {
            if (origin(h) != v || ++degree > halfEdgeCount()) fail(fmt::format("vertex {}: broken edge ring", v));
            normal_sum += face_normal_[face(h)];
            h = nextAroundOrigin(h);
        } while (h != vertex_edge_[v]);
        if (degree < 3) fail(fmt::format("vertex {} has degree {} (< 3)", v, degree));
        ring_total += degree;
        h = vertex_edge_[v];   // vertex region non-empty: the mean normal is inside every edge plane
        do {
            if (edgeDir(h).dot(normal_sum) >= 0.0) fail(fmt::format("vertex {} {} is not convex (Voronoi cone empty)", v, vecText(positions_[v])));
            h = nextAroundOrigin(h);
        } while (h != vertex_edge_[v]);
    }
    if (ring_total != halfEdgeCount()) fail("non-manifold vertex (edge rings do not cover all half-edges)");
    for (int f = 0; f < faceCount(); ++f) {
        const Vec3& n = face_normal_[f];
        if (std::abs(n.norm() - 1.0) > 1e-9) fail(fmt::format("face {} normal is not unit", f));
        Vec3 newell = Vec3::Zero(), centre = Vec3::Zero();
        int h = face_edge_[f];
        for (int k = 0; k < face_size_[f]; ++k, h = next(h)) {
            const Vec3& p = position(origin(h));
            const Vec3& q = position(destination(h));
            newell += p.cross(q);
            centre += p;
            if (std::abs(faceDistance(f, p)) > tol) fail(fmt::format("face {} is not planar at vertex {}", f, origin(h)));
        }
        if (h != face_edge_[f]) fail(fmt::format("face {}: broken edge loop", f));
        if (newell.dot(n) <= 0.0) fail(fmt::format("face {} is not counter-clockwise seen from outside", f));
        centre /= face_size_[f];
        h = face_edge_[f];
        for (int k = 0; k < face_size_[f]; ++k, h = next(h))   // face prism contains its centre
            if (sideNormal(h).dot(centre - position(origin(h))) >= 0.0) fail(fmt::format("face {} is not convex", f));
        for (int v = 0; v < vertexCount(); ++v)
            if (faceDistance(f, positions_[v]) > tol) fail(fmt::format("not convex: vertex {} is {} m above face {}", v, faceDistance(f, positions_[v]), f));
    }
    for (int h = 0; h < halfEdgeCount(); h += 2) {
        const Vec3 bisector = face_normal_[face(h)] + face_normal_[face(h ^ 1)];
        if (sideNormal(h).dot(bisector) <= 0.0 || sideNormal(h ^ 1).dot(bisector) <= 0.0)
            fail(fmt::format("edge {}-{}: faces {} and {} are coplanar or reflex (merge coplanar faces)", origin(h), destination(h), face(h), face(h ^ 1)));
    }
}

int ConvexMesh::supportVertex(const Vec3& dir, int start) const {
    int best = start;
    double best_value = dir.dot(positions_[best]);
    for (bool improved = true; improved;) {
        improved = false;
        const int first = vertex_edge_[best];
        int h = first;
        do {
            const int w = destination(h);
            const double value = dir.dot(positions_[w]);
            if (value > best_value) {
                best = w;
                best_value = value;
                improved = true;
                break;
            }
            h = nextAroundOrigin(h);
        } while (h != first);
    }
    return best;
}

ConvexPolyhedron ConvexMesh::toPolyhedron() const {
    ConvexPolyhedron poly;
    poly.vertices = positions_;
    for (int f = 0; f < faceCount(); ++f) {
        std::vector<int> ids;
        int h = face_edge_[f];
        for (int k = 0; k < face_size_[f]; ++k, h = next(h)) ids.push_back(origin(h));
        poly.faces.push_back(std::move(ids));
        poly.face_normals.push_back(face_normal_[f]);
        poly.face_offsets.push_back(face_offset_[f]);
    }
    return poly;
}

}  // namespace vroc::native
