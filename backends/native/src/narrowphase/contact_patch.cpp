// SPDX-License-Identifier: MIT
// Contact region of a touching pair. Each body contributes the face, edge or vertex that lies
// (within `tolerance`) on its supporting plane at the closest point; face against face gives
// the Sutherland–Hodgman overlap polygon, edge against face the clipped segment, parallel edges
// their overlap, anything else the single closest point. Results are projected to the plane
// half-way between the two surfaces.
#include <cmath>

#include "geometry/convex_mesh.h"
#include "narrowphase/contact_patch.h"

namespace vroc::native {
namespace {

/// Orthonormal basis (u, w) of the plane perpendicular to unit n, (u, w, n) right-handed.
void planeBasis(const Vec3& n, Vec3& u, Vec3& w) {
    u = (std::abs(n.x()) < 0.6 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized();
    w = n.cross(u);
}

std::vector<Vec3> faceWorld(const ConvexMesh& m, const Pose& pose, int f) {
    std::vector<Vec3> pts;
    int h = m.faceEdge(f);
    for (int k = 0; k < m.faceSize(f); ++k, h = m.next(h)) pts.push_back(pose.apply(m.position(m.origin(h))));
    return pts;
}

bool onPlane(const std::vector<Vec3>& pts, const Vec3& dir, const Vec3& at, double tol) {
    for (const Vec3& p : pts)
        if (dir.dot(p - at) < -tol) return false;
    return true;
}

/// The piece of body m (feature f) lying on its support plane along world direction `dir`
/// through `at`: a face polygon (CCW seen along dir), an edge (2 points), or the point.
std::vector<Vec3> supportPiece(const ConvexMesh& m, const Pose& pose, Feature f, const Vec3& dir,
                               const Vec3& at, double tol) {
    std::vector<int> faces, edges;
    if (f.type == FeatureType::Face) {
        faces.push_back(f.index);
        int h = m.faceEdge(f.index);
        for (int k = 0; k < m.faceSize(f.index); ++k, h = m.next(h)) edges.push_back(h);
    } else if (f.type == FeatureType::Edge) {
        faces = {m.face(f.index), m.face(f.index ^ 1)};
        edges.push_back(f.index);
    } else if (f.type == FeatureType::Vertex) {
        const int first = m.vertexEdge(f.index);
        for (int h = first;;) {
            faces.push_back(m.face(h));
            edges.push_back(h);
            if ((h = m.nextAroundOrigin(h)) == first) break;
        }
    }
    int best_face = -1;
    for (int g : faces)
        if (onPlane(faceWorld(m, pose, g), dir, at, tol) &&
            (best_face < 0 || pose.rotate(m.faceNormal(g)).dot(dir) > pose.rotate(m.faceNormal(best_face)).dot(dir)))
            best_face = g;
    if (best_face >= 0) return faceWorld(m, pose, best_face);
    for (int h : edges) {
        std::vector<Vec3> seg{pose.apply(m.position(m.origin(h))), pose.apply(m.position(m.destination(h)))};
        if (onPlane(seg, dir, at, tol)) return seg;
    }
    return {at};
}

using Poly2 = std::vector<Eigen::Vector2d>;

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

/// Sutherland–Hodgman: subject clipped by the convex CCW polygon `clip`.
Poly2 clipPolygon(Poly2 subject, const Poly2& clip) {
    for (size_t i = 0; i < clip.size() && !subject.empty(); ++i) {
        const Eigen::Vector2d a = clip[i], e = clip[(i + 1) % clip.size()] - a;
        Poly2 out;
        for (size_t k = 0; k < subject.size(); ++k) {
            const Eigen::Vector2d p = subject[k], q = subject[(k + 1) % subject.size()];
            const double dp = cross2(e, p - a), dq = cross2(e, q - a);   // >= 0: inside (left)
            if (dp >= 0.0) out.push_back(p);
            if ((dp >= 0.0) != (dq >= 0.0)) out.push_back(p + (dp / (dp - dq)) * (q - p));
        }
        subject = std::move(out);
    }
    return subject;
}

/// Segment pq clipped to the convex CCW polygon (2D); empty if outside.
Poly2 clipSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Poly2& clip) {
    double lo = 0.0, hi = 1.0;
    for (size_t i = 0; i < clip.size(); ++i) {
        const Eigen::Vector2d a = clip[i], e = clip[(i + 1) % clip.size()] - a;
        const double dp = cross2(e, p - a), dq = cross2(e, q - a);
        if (dp < 0.0 && dq < 0.0) return {};
        if (dp < 0.0) lo = std::max(lo, dp / (dp - dq));
        else if (dq < 0.0) hi = std::min(hi, dp / (dp - dq));
    }
    if (lo > hi) return {};
    return {p + lo * (q - p), p + hi * (q - p)};
}

}  // namespace

ContactPatch contactPatch(const ConvexMesh& a, const Pose& pose_a, const ConvexMesh& b, const Pose& pose_b,
                          const FeatureCache& cache, const ProximityResult& result, double tolerance) {
    const Vec3 n = result.normal;
    const Vec3 mid = 0.5 * (result.point_a + result.point_b);
    std::vector<Vec3> pa = supportPiece(a, pose_a, cache.a, n, result.point_a, tolerance);
    std::vector<Vec3> pb = supportPiece(b, pose_b, cache.b, -n, result.point_b, tolerance);
    Vec3 u, w;
    planeBasis(n, u, w);
    auto to2 = [&](const Vec3& x) { return Eigen::Vector2d((x - mid).dot(u), (x - mid).dot(w)); };
    auto to3 = [&](const Eigen::Vector2d& x) { return Vec3(mid + x.x() * u + x.y() * w); };
    Poly2 a2, b2, out;
    for (const Vec3& x : pa) a2.push_back(to2(x));
    for (auto it = pb.rbegin(); it != pb.rend(); ++it) b2.push_back(to2(*it));   // B's CCW is about -n
    if (a2.size() >= 3 && b2.size() >= 3) out = clipPolygon(b2, a2);
    else if (a2.size() >= 3 && b2.size() == 2) out = clipSegment(b2[0], b2[1], a2);
    else if (b2.size() >= 3 && a2.size() == 2) out = clipSegment(a2[0], a2[1], b2);
    else if (a2.size() == 2 && b2.size() == 2) {   // parallel edges: overlap along a's direction
        const Eigen::Vector2d d = a2[1] - a2[0];
        if (std::abs(cross2(d.normalized(), b2[1] - b2[0])) <= tolerance) {
            const double dd = d.squaredNorm();
            const double t0 = (b2[0] - a2[0]).dot(d) / dd, t1 = (b2[1] - a2[0]).dot(d) / dd;
            const double lo = std::max(0.0, std::min(t0, t1)), hi = std::min(1.0, std::max(t0, t1));
            if (lo <= hi) out = {a2[0] + lo * d, a2[0] + hi * d};
        }
    }
    ContactPatch patch;
    if (out.empty()) {
        patch.points = {mid};
        patch.centroid = mid;
        return patch;
    }
    double area = 0.0;
    Eigen::Vector2d c = Eigen::Vector2d::Zero(), mean = Eigen::Vector2d::Zero();
    for (size_t k = 0; k < out.size(); ++k) {
        const double cr = cross2(out[k], out[(k + 1) % out.size()]);
        area += cr;
        c += cr * (out[k] + out[(k + 1) % out.size()]);
        mean += out[k];
        patch.points.push_back(to3(out[k]));
    }
    mean /= static_cast<double>(out.size());
    // Area centroid for a polygon; the mean for a segment, a point or a degenerate sliver.
    const double scale2 = (out.front() - mean).squaredNorm() + 1e-300;
    patch.centroid = to3(out.size() >= 3 && std::abs(area) > 1e-12 * scale2 ? Eigen::Vector2d(c / (3.0 * area)) : mean);
    return patch;
}

}  // namespace vroc::native
