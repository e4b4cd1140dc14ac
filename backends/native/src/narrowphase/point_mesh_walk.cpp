// SPDX-License-Identifier: MIT
// The point walk is Lin–Canny with one body shrunk to a point: a violated Voronoi plane names a
// neighbour strictly closer to the point (or as close and of lower dimension), so it terminates;
// a point under a face plane inside its prism is resolved by the O(n) face scan (inside the mesh,
// or a jump to a face the point is above).
#include "narrowphase/point_mesh_walk.h"

#include <limits>

#include "geometry/closest_points.h"

namespace vroc::native {
namespace {

enum class Move : std::uint8_t { Continue, Done };

Vec3 onEdge(const ConvexMesh& m, int h, const Vec3& p) {
    const Vec3& a = m.position(m.origin(h));
    const Vec3& b = m.position(m.destination(h));
    return a + closestOnSegment(p, a, b) * (b - a);
}

Move fromVertex(const ConvexMesh& m, const Vec3& p, PointWalkResult& r) {
    const Vec3& v = m.position(r.feature.index);
    const int first = m.vertexEdge(r.feature.index);
    for (int h = first;;) {
        if (m.edgeDir(h).dot(p - v) > 0.0) { r.feature = {FeatureType::Edge, h}; return Move::Continue; }
        if ((h = m.nextAroundOrigin(h)) == first) break;
    }
    r.closest = v;
    r.signed_distance = (p - v).norm();
    return Move::Done;
}

Move fromEdge(const ConvexMesh& m, const Vec3& p, PointWalkResult& r) {
    const int h = r.feature.index;
    const Vec3& a = m.position(m.origin(h));
    const Vec3& b = m.position(m.destination(h));
    if (m.edgeDir(h).dot(p - a) < 0.0) { r.feature = {FeatureType::Vertex, m.origin(h)}; return Move::Continue; }
    if (m.edgeDir(h).dot(p - b) > 0.0) { r.feature = {FeatureType::Vertex, m.destination(h)}; return Move::Continue; }
    if (m.sideNormal(h).dot(p - a) < 0.0) { r.feature = {FeatureType::Face, m.face(h)}; return Move::Continue; }
    if (m.sideNormal(h ^ 1).dot(p - b) < 0.0) { r.feature = {FeatureType::Face, m.face(h ^ 1)}; return Move::Continue; }
    r.closest = onEdge(m, h, p);
    r.signed_distance = (p - r.closest).norm();
    return Move::Done;
}

/// Largest signed distance over all faces (the O(n) scan).
int maxDistanceFace(const ConvexMesh& m, const Vec3& p) {
    int best = 0;
    for (int f = 1; f < m.faceCount(); ++f)
        if (m.faceDistance(f, p) > m.faceDistance(best, p)) best = f;
    return best;
}

Move fromFace(const ConvexMesh& m, const Vec3& p, PointWalkResult& r) {
    const int f = r.feature.index;
    int h = m.faceEdge(f);
    bool outside_prism = false;
    for (int k = 0; k < m.faceSize(f) && !outside_prism; ++k, h = m.next(h))
        outside_prism = m.sideNormal(h).dot(p - m.position(m.origin(h))) > 0.0;
    if (outside_prism) {   // the boundary edge closest to p (keeps the distance, lowers dimension)
        int best = -1;
        double best_d2 = std::numeric_limits<double>::infinity();
        h = m.faceEdge(f);
        for (int k = 0; k < m.faceSize(f); ++k, h = m.next(h)) {
            const double d2 = (p - onEdge(m, h, p)).squaredNorm();
            if (d2 < best_d2) { best_d2 = d2; best = h; }
        }
        r.feature = {FeatureType::Edge, best};
        return Move::Continue;
    }
    const double d = m.faceDistance(f, p);
    if (d <= 0.0) {
        const int g = maxDistanceFace(m, p);
        const double dg = m.faceDistance(g, p);
        if (dg > 0.0) { r.feature = {FeatureType::Face, g}; return Move::Continue; }
        r.feature = {FeatureType::Face, g};
        r.closest = p - dg * m.faceNormal(g);
        r.signed_distance = dg;
        return Move::Done;
    }
    r.closest = p - d * m.faceNormal(f);
    r.signed_distance = d;
    return Move::Done;
}

bool valid(const ConvexMesh& m, Feature f) {
    switch (f.type) {
        case FeatureType::Vertex: return f.index >= 0 && f.index < m.vertexCount();
        case FeatureType::Edge: return f.index >= 0 && f.index < m.halfEdgeCount();
        case FeatureType::Face: return f.index >= 0 && f.index < m.faceCount();
        default: return false;
    }
}

/// The fallback (never expected): every vertex, edge and face, O(n).
void scanAll(const ConvexMesh& m, const Vec3& p, PointWalkResult& r) {
    const int g = maxDistanceFace(m, p);
    if (m.faceDistance(g, p) <= 0.0) {
        r.feature = {FeatureType::Face, g};
        r.signed_distance = m.faceDistance(g, p);
        r.closest = p - r.signed_distance * m.faceNormal(g);
        return;
    }
    double best = std::numeric_limits<double>::infinity();
    auto offer = [&](Feature f, const Vec3& c) {
        const double d = (p - c).norm();
        if (d < best) { best = d; r.feature = f; r.closest = c; }
    };
    for (int v = 0; v < m.vertexCount(); ++v) offer({FeatureType::Vertex, v}, m.position(v));
    for (int h = 0; h < m.halfEdgeCount(); h += 2) offer({FeatureType::Edge, h}, onEdge(m, h, p));
    for (int f = 0; f < m.faceCount(); ++f) {
        const Vec3 c = p - m.faceDistance(f, p) * m.faceNormal(f);
        bool inside = true;
        int h = m.faceEdge(f);
        for (int k = 0; k < m.faceSize(f); ++k, h = m.next(h))
            inside = inside && m.sideNormal(h).dot(c - m.position(m.origin(h))) <= 0.0;
        if (inside) offer({FeatureType::Face, f}, c);
    }
    r.signed_distance = best;
}

}  // namespace

PointWalkResult closestFeatureToPoint(const ConvexMesh& m, const Vec3& p, Feature start) {
    PointWalkResult r;
    r.feature = valid(m, start) ? start : Feature{FeatureType::Vertex, m.supportVertex(p - m.centroid())};
    const int bound = 4 * m.edgeCount() + 64;
    for (r.steps = 0; r.steps <= bound; ++r.steps) {
        Move move = Move::Continue;
        switch (r.feature.type) {
            case FeatureType::Vertex: move = fromVertex(m, p, r); break;
            case FeatureType::Edge: move = fromEdge(m, p, r); break;
            default: move = fromFace(m, p, r); break;
        }
        if (move == Move::Done) return r;
    }
    r.converged = false;
    scanAll(m, p, r);
    return r;
}

}  // namespace vroc::native
