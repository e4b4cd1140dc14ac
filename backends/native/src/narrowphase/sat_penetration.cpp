// SPDX-License-Identifier: MIT
#include "narrowphase/sat_penetration.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "geometry/closest_points.h"

namespace vroc::native {
namespace {

// Everything is computed in A's frame: B's vertices and face normals turned once.
struct Scratch {
    std::vector<Vec3> vertices_b, normals_b;
};

Scratch& scratch() {
    thread_local Scratch s;
    return s;
}

/// The edge arcs (a1, a2) of A and (c1, c2) of -B on the unit sphere cross: the two edges' cross
/// product is the normal of a face of the Minkowski difference (Gregorius 2013).
bool minkowskiFace(const Vec3& a1, const Vec3& a2, const Vec3& c1, const Vec3& c2) {
    const Vec3 a_arc = a2.cross(a1), c_arc = c2.cross(c1);
    const double c1a = c1.dot(a_arc), c2a = c2.dot(a_arc), a1c = a1.dot(c_arc), a2c = a2.dot(c_arc);
    return c1a * c2a < 0.0 && a1c * a2c < 0.0 && c1a * a2c > 0.0;
}

}  // namespace

SatPenetration satPenetration(const ConvexMesh& a, const Pose& pose_a, const ConvexMesh& b, const Pose& pose_b) {
    const Pose rel = pose_a.inverse() * pose_b;   // B's frame -> A's
    Scratch& sc = scratch();
    std::vector<Vec3>& vb = sc.vertices_b;
    std::vector<Vec3>& nb = sc.normals_b;
    vb.clear();
    nb.clear();
    for (int v = 0; v < b.vertexCount(); ++v) vb.push_back(rel.apply(b.position(v)));
    for (int f = 0; f < b.faceCount(); ++f) nb.push_back(rel.rotate(b.faceNormal(f)));
    auto lowestOfB = [&](const Vec3& n, int& at) {   // min over B of n . x (a plain scan: B is small)
        double lo = std::numeric_limits<double>::infinity();
        for (std::size_t v = 0; v < vb.size(); ++v) {
            const double h = n.dot(vb[v]);
            if (h < lo) {
                lo = h;
                at = static_cast<int>(v);
            }
        }
        return lo;
    };

    SatPenetration r;
    double best = std::numeric_limits<double>::infinity();
    Vec3 n_best = Vec3::UnitX();
    int vertex_b = -1, vertex_a = -1;   // the deepest vertex of the other body, for a face axis
    // Faces of A: the face's plane bounds A along its normal.
    for (int f = 0; f < a.faceCount(); ++f) {
        int at = 0;
        const double depth = a.faceOffset(f) - lowestOfB(a.faceNormal(f), at);
        if (depth < best) {
            best = depth;
            n_best = a.faceNormal(f);
            r.axis = SatAxis::FaceA;
            r.feature_a = f;
            vertex_b = at;
        }
    }
    // Faces of B: the normal from A towards B is minus B's outward normal.
    int hint = 0;
    for (int f = 0; f < b.faceCount(); ++f) {
        const Vec3 n = -nb[static_cast<std::size_t>(f)];
        hint = a.supportVertex(n, hint);
        const double top_b = nb[static_cast<std::size_t>(f)].dot(vb[static_cast<std::size_t>(b.origin(b.faceEdge(f)))]);
        const double depth = n.dot(a.position(hint)) + top_b;
        if (depth < best) {
            best = depth;
            n_best = n;
            r.axis = SatAxis::FaceB;
            r.feature_b = f;
            vertex_a = hint;
        }
    }
    // Edge pairs that make a face of the Minkowski difference. A face axis wins ties within rounding.
    const double face_best = best;
    const double tie = 64.0 * std::numeric_limits<double>::epsilon() * (a.scale() + b.scale() + rel.position.norm());
    int edge_a = -1, edge_b = -1;
    for (int ea = 0; ea < a.edgeCount(); ++ea) {
        const int h = 2 * ea;
        const Vec3& a1 = a.faceNormal(a.face(h));
        const Vec3& a2 = a.faceNormal(a.face(h ^ 1));
        const Vec3& pa = a.position(a.origin(h));
        for (int eb = 0; eb < b.edgeCount(); ++eb) {
            const int g = 2 * eb;
            const Vec3& b1 = nb[static_cast<std::size_t>(b.face(g))];
            const Vec3& b2 = nb[static_cast<std::size_t>(b.face(g ^ 1))];
            if (!minkowskiFace(a1, a2, -b1, -b2)) continue;
            const Vec3 pb = vb[static_cast<std::size_t>(b.origin(g))];
            const Vec3 db = vb[static_cast<std::size_t>(b.destination(g))] - pb;
            Vec3 n = a.edgeDir(h).cross(db);
            const double len = n.norm();
            if (!(len > 1e-9 * db.norm())) continue;   // parallel edges: their faces' axes cover them
            n /= len;
            if (n.dot(pa - a.centroid()) < 0.0) n = -n;   // outward from A at its edge
            const double depth = n.dot(pa) - n.dot(pb);
            if (depth < best && depth < face_best - tie) {
                best = depth;
                n_best = n;
                edge_a = h;
                edge_b = g;
            }
        }
    }
    // The deepest points, in A's frame.
    Vec3 point_a, point_b;
    if (edge_a >= 0) {
        r.axis = SatAxis::EdgeEdge;
        r.feature_a = edge_a / 2;
        r.feature_b = edge_b / 2;
        const Vec3& pa0 = a.position(a.origin(edge_a));
        const Vec3& pa1 = a.position(a.destination(edge_a));
        const Vec3& pb0 = vb[static_cast<std::size_t>(b.origin(edge_b))];
        const Vec3& pb1 = vb[static_cast<std::size_t>(b.destination(edge_b))];
        const SegmentParams st = closestSegmentSegment(pa0, pa1, pb0, pb1);
        point_a = pa0 + st.s * (pa1 - pa0);
        point_b = pb0 + st.t * (pb1 - pb0);
    } else if (r.axis == SatAxis::FaceA) {
        point_b = vb[static_cast<std::size_t>(vertex_b)];
        point_a = point_b + best * n_best;
    } else {
        point_a = a.position(vertex_a);
        point_b = point_a - best * n_best;
    }
    r.depth = best;
    r.normal = pose_a.rotate(n_best);
    r.point_a = pose_a.apply(point_a);
    r.point_b = pose_a.apply(point_b);
    return r;
}

}  // namespace vroc::native
