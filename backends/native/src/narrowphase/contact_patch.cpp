// SPDX-License-Identifier: MIT
// Contact region of a touching pair. Each body contributes the face, edge or vertex that lies
// (within `tolerance`) on its supporting plane at the closest point; face against face gives
// the Sutherland–Hodgman overlap polygon, edge against face the clipped segment, parallel edges
// their overlap, anything else the single closest point. Results are projected to the plane
// half-way between the two surfaces.
#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/convex_mesh.h"
#include "narrowphase/contact_patch.h"

namespace vroc::native {
namespace {

/// Orthonormal basis (u, w) of the plane perpendicular to unit n, (u, w, n) right-handed.
void planeBasis(const Vec3& n, Vec3& u, Vec3& w) {
    u = (std::abs(n.x()) < 0.6 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized();
    w = n.cross(u);
}

// The patch is computed on every solve of every touching pair, so its working polygons live in
// per-thread scratch buffers that keep their capacity (no heap allocation once warm; the narrow
// phase runs on several workers, each with its own). Each buffer has one use at a time.
struct Scratch {
    std::vector<int> faces, edges;
    std::vector<Vec3> piece_a, piece_b;
    std::vector<Vec3> normals_a, normals_b;   // world face normals of the two bodies
    std::vector<Eigen::Vector2d> a2, b2, out, clip_buffer, kept;
};

Scratch& scratch() {
    thread_local Scratch s;
    return s;
}

/// Face f's vertices in world coordinates, into `pts` (cleared first).
void faceWorld(const ConvexMesh& m, const Pose& pose, int f, std::vector<Vec3>& pts) {
    pts.clear();
    int h = m.faceEdge(f);
    for (int k = 0; k < m.faceSize(f); ++k, h = m.next(h)) pts.push_back(pose.apply(m.position(m.origin(h))));
}

/// True if no vertex of face f lies more than tol below the plane through `at` along dir.
bool faceOnPlane(const ConvexMesh& m, const Pose& pose, int f, const Vec3& dir, const Vec3& at, double tol) {
    int h = m.faceEdge(f);
    for (int k = 0; k < m.faceSize(f); ++k, h = m.next(h))
        if (dir.dot(pose.apply(m.position(m.origin(h))) - at) < -tol) return false;
    return true;
}

/// The piece of body m (feature f) lying on its support plane along world direction `dir`
/// through `at`, into `piece`: a face polygon (CCW seen along dir), an edge (2 points), or the point.
void supportPiece(const ConvexMesh& m, const Pose& pose, Feature f, const Vec3& dir, const Vec3& at, double tol,
                  std::vector<Vec3>& piece) {
    std::vector<int>& faces = scratch().faces;
    std::vector<int>& edges = scratch().edges;
    faces.clear();
    edges.clear();
    if (f.type == FeatureType::Face) {
        faces.push_back(f.index);
        int h = m.faceEdge(f.index);
        for (int k = 0; k < m.faceSize(f.index); ++k, h = m.next(h)) edges.push_back(h);
    } else if (f.type == FeatureType::Edge) {
        faces.push_back(m.face(f.index));
        faces.push_back(m.face(f.index ^ 1));
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
        if (faceOnPlane(m, pose, g, dir, at, tol) &&
            (best_face < 0 || pose.rotate(m.faceNormal(g)).dot(dir) > pose.rotate(m.faceNormal(best_face)).dot(dir)))
            best_face = g;
    if (best_face >= 0) {
        faceWorld(m, pose, best_face, piece);
        return;
    }
    for (int h : edges) {
        const Vec3 p = pose.apply(m.position(m.origin(h))), q = pose.apply(m.position(m.destination(h)));
        if (!(dir.dot(p - at) < -tol) && !(dir.dot(q - at) < -tol)) {
            piece.assign({p, q});
            return;
        }
    }
    piece.assign(1, at);
}

using Poly2 = std::vector<Eigen::Vector2d>;

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

/// Sutherland–Hodgman: `subject` clipped by the convex CCW polygon `clip`, into `result` (a scratch
/// buffer: it trades storage with the clipping buffer at every edge).
void clipPolygon(const Poly2& subject, const Poly2& clip, Poly2& result) {
    Poly2& out = scratch().clip_buffer;
    result.assign(subject.begin(), subject.end());
    for (size_t i = 0; i < clip.size() && !result.empty(); ++i) {
        const Eigen::Vector2d a = clip[i], e = clip[(i + 1) % clip.size()] - a;
        out.clear();
        for (size_t k = 0; k < result.size(); ++k) {
            const Eigen::Vector2d p = result[k], q = result[(k + 1) % result.size()];
            const double dp = cross2(e, p - a), dq = cross2(e, q - a);   // >= 0: inside (left)
            if (dp >= 0.0) out.push_back(p);
            if ((dp >= 0.0) != (dq >= 0.0)) out.push_back(p + (dp / (dp - dq)) * (q - p));
        }
        std::swap(result, out);
    }
}

/// Segment pq clipped to the convex CCW polygon (2D), into `result`; empty if outside.
void clipSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Poly2& clip, Poly2& result) {
    result.clear();
    double lo = 0.0, hi = 1.0;
    for (size_t i = 0; i < clip.size(); ++i) {
        const Eigen::Vector2d a = clip[i], e = clip[(i + 1) % clip.size()] - a;
        const double dp = cross2(e, p - a), dq = cross2(e, q - a);
        if (dp < 0.0 && dq < 0.0) return;
        if (dp < 0.0) lo = std::max(lo, dp / (dp - dq));
        else if (dq < 0.0) hi = std::min(hi, dp / (dp - dq));
    }
    if (lo > hi) return;
    result.push_back(p + lo * (q - p));
    result.push_back(p + hi * (q - p));
}

/// A piece's plane (Newell's normal, robust for any planar polygon), computed once per piece: a
/// patch asks for the piece's height above a dozen or more points.
struct PiecePlane {
    Vec3 normal = Vec3::Zero();
    double along = 0.0;     ///< normal . n
    bool planar = false;    ///< a face not edge-on to n: heights come from its plane
};

PiecePlane piecePlane(const std::vector<Vec3>& pts, const Vec3& n) {
    PiecePlane plane;
    if (pts.size() < 3) return plane;
    for (std::size_t k = 0; k < pts.size(); ++k) plane.normal += pts[k].cross(pts[(k + 1) % pts.size()]);
    plane.along = plane.normal.dot(n);
    plane.planar = std::abs(plane.along) > 1e-9 * plane.normal.norm();
    return plane;
}

/// [m] the height along n (from `mid`) of the piece `pts` (world; its plane `plane`) above the
/// mid-plane point at 2D coordinates x: on the piece's plane for a face, along its line for an
/// edge, its own for a point.
double pieceHeight(const std::vector<Vec3>& pts, const PiecePlane& plane, const Eigen::Vector2d& x, const Vec3& mid,
                   const Vec3& u, const Vec3& w, const Vec3& n) {
    const Vec3 at = mid + x.x() * u + x.y() * w;
    if (plane.planar) return plane.normal.dot(pts[0] - at) / plane.along;
    if (pts.size() >= 2) {
        const Vec3 d = pts[1] - pts[0];
        const Vec3 dp = d - d.dot(n) * n;   // the edge's direction in the plane
        const double len2 = dp.squaredNorm();
        const double s = len2 > 0.0 ? std::clamp((at - pts[0]).dot(dp) / len2, 0.0, 1.0) : 0.0;
        return (pts[0] + s * d - mid).dot(n);
    }
    return (pts[0] - mid).dot(n);
}

/// [m] the height along n (from `mid`) of body m's surface on the line through the mid-plane point
/// x along n: its top (side = +1) or bottom (side = -1), from the face planes (a convex body is the
/// intersection of its faces' half-spaces). NaN if the line misses it.
double surfaceHeight(const ConvexMesh& m, const Pose& pose, const Eigen::Vector2d& x, const Vec3& mid, const Vec3& u,
                     const Vec3& w, const Vec3& n, double side) {
    const Vec3 at = mid + x.x() * u + x.y() * w;
    // Points on the body's outline (a face parallel to n, an edge) count as on it: rounding must not
    // make the line through a vertex miss the body it belongs to.
    const double eps = 1e-9 * (1.0 + (pose.position - at).norm());
    double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
    for (int f = 0; f < m.faceCount(); ++f) {
        const Vec3 fn = pose.rotate(m.faceNormal(f));
        const int h = m.faceEdge(f);
        const double offset = fn.dot(pose.apply(m.position(m.origin(h))) - at);   // fn.(z n) <= offset
        const double along = fn.dot(n);
        if (along > 1e-9) hi = std::min(hi, offset / along);
        else if (along < -1e-9) lo = std::max(lo, offset / along);
        else if (offset < -eps) return std::numeric_limits<double>::quiet_NaN();
    }
    if (lo > hi + eps) return std::numeric_limits<double>::quiet_NaN();
    if (lo > hi) return 0.5 * (lo + hi);
    return side > 0.0 ? hi : lo;
}

/// The face of the feature (or around it) whose world normal (`normals`, per face) is most aligned
/// with `dir`; of all the body's faces if `any_face`.
int alignedFace(const ConvexMesh& m, const std::vector<Vec3>& normals, Feature f, const Vec3& dir, bool any_face) {
    std::vector<int>& faces = scratch().faces;
    faces.clear();
    if (any_face) {
        for (int g = 0; g < m.faceCount(); ++g) faces.push_back(g);
    } else if (f.type == FeatureType::Face) {
        return f.index;
    } else if (f.type == FeatureType::Edge) {
        faces.push_back(m.face(f.index));
        faces.push_back(m.face(f.index ^ 1));
    } else if (f.type == FeatureType::Vertex) {
        const int first = m.vertexEdge(f.index);
        for (int h = first;;) {
            faces.push_back(m.face(h));
            if ((h = m.nextAroundOrigin(h)) == first) break;
        }
    }
    int best = -1;
    double best_dot = -2.0;
    for (int g : faces) {
        const double d = normals[static_cast<std::size_t>(g)].dot(dir);
        if (d > best_dot) {
            best_dot = d;
            best = g;
        }
    }
    return best;
}

/// The world normals of m's faces at `pose`, into `normals`.
void worldNormals(const ConvexMesh& m, const Pose& pose, std::vector<Vec3>& normals) {
    normals.clear();
    for (int f = 0; f < m.faceCount(); ++f) normals.push_back(pose.rotate(m.faceNormal(f)));
}

/// Faces fa of A and fb of B (world normals `normals_a`, `normals_b`) clipped, points kept within
/// `reach` (see contactPatch), into the empty `patch`; left empty when nothing touches.
void clipFaces(const ConvexMesh& a, const Pose& pose_a, const ConvexMesh& b, const Pose& pose_b,
               const std::vector<Vec3>& normals_a, const std::vector<Vec3>& normals_b, int fa, int fb,
               const ProximityResult& result, double tolerance, double reach, ContactPatch& patch) {
    const Vec3 n = result.normal;
    std::vector<Vec3>& pa = scratch().piece_a;
    std::vector<Vec3>& pb = scratch().piece_b;
    faceWorld(a, pose_a, fa, pa);
    faceWorld(b, pose_b, fb, pb);
    const Vec3 mid = 0.5 * (result.point_a + result.point_b);
    Vec3 u, w;
    planeBasis(n, u, w);
    auto to2 = [&](const Vec3& x) { return Eigen::Vector2d((x - mid).dot(u), (x - mid).dot(w)); };
    Poly2& a2 = scratch().a2;
    Poly2& b2 = scratch().b2;
    a2.clear();
    b2.clear();
    for (const Vec3& x : pa) a2.push_back(to2(x));
    for (auto it = pb.rbegin(); it != pb.rend(); ++it) b2.push_back(to2(*it));   // B's CCW is about -n
    // Candidates: the overlap of the two faces (where their edges cross), and every vertex of either
    // body within reach of the other's face plane over that face: a box tipping over an edge brings
    // down the vertices of the face beyond the edge, which the incident face does not hold.
    // Each candidate with its height on B's surface (nan: from B's surface over x) and on A's.
    struct Candidate {
        Eigen::Vector2d x;
        double on_b, on_a;
    };
    const double nan = std::numeric_limits<double>::quiet_NaN();
    thread_local std::vector<Candidate> candidates;   // per worker, reused: no allocation once warm
    candidates.clear();
    Poly2& overlap = scratch().out;
    clipPolygon(b2, a2, overlap);
    for (const Eigen::Vector2d& x : overlap) candidates.push_back({x, nan, nan});
    // A vertex on the face's outline counts as over it, to rounding. Two edges meeting edge-on (cubes
    // turned 45 degrees, side by side) have faces that share only that line: a turn of 1e-15 rad, from
    // rounding, left one end of the edge outside and the patch a sliver at the other, and the impact
    // there set the cubes spinning. (A margin of `tolerance` also holds a real turn of 1e-6 rad, but
    // makes the patch depend on which of two equally close features the walk stopped at: pair bounds
    // then changed results, NativeFixedTicks.PairBoundsSkipQueriesNotResults.)
    auto inside = [](const Poly2& poly, const Eigen::Vector2d& x) {
        for (std::size_t i = 0; i < poly.size(); ++i) {
            const Eigen::Vector2d e = poly[(i + 1) % poly.size()] - poly[i], r = x - poly[i];
            if (cross2(e, r) < -1e-9 * e.norm() * (e.norm() + r.norm())) return false;
        }
        return true;
    };
    // A vertex on its body's far side (every face around it turned away from the other body) is not
    // where the bodies would meet: the surface below it is.
    auto facing = [](const ConvexMesh& m, const std::vector<Vec3>& normals, int v, const Vec3& towards) {
        const int first = m.vertexEdge(v);
        for (int h = first;;) {
            if (normals[static_cast<std::size_t>(m.face(h))].dot(towards) >= -1e-9) return true;
            if ((h = m.nextAroundOrigin(h)) == first) return false;
        }
    };
    const PiecePlane plane_a = piecePlane(pa, n), plane_b = piecePlane(pb, n);
    for (int v = 0; v < b.vertexCount(); ++v) {
        if (!facing(b, normals_b, v, -n)) continue;
        const Vec3 x = pose_b.apply(b.position(v));
        const double on_b = (x - mid).dot(n);
        const Eigen::Vector2d x2 = to2(x);
        if (on_b - pieceHeight(pa, plane_a, x2, mid, u, w, n) <= reach && inside(a2, x2)) candidates.push_back({x2, on_b, nan});
    }
    for (int v = 0; v < a.vertexCount(); ++v) {
        if (!facing(a, normals_a, v, n)) continue;
        const Vec3 y = pose_a.apply(a.position(v));
        const double on_a = (y - mid).dot(n);
        const Eigen::Vector2d y2 = to2(y);
        if (pieceHeight(pb, plane_b, y2, mid, u, w, n) - on_a <= reach && inside(b2, y2)) candidates.push_back({y2, nan, on_a});
    }
    const bool a_faces = normals_a[static_cast<std::size_t>(fa)].dot(n) > 1e-9;
    const bool b_faces = normals_b[static_cast<std::size_t>(fb)].dot(n) < -1e-9;
    Vec3 touching_sum = Vec3::Zero();
    int touching = 0;
    const double merge2 = 1e-12 * (a2.empty() ? 1.0 : (a2[0].squaredNorm() + 1.0));
    std::vector<Eigen::Vector2d>& kept = scratch().kept;
    kept.clear();
    for (const Candidate& c : candidates) {
        const Eigen::Vector2d& x = c.x;
        if (std::any_of(kept.begin(), kept.end(), [&](const Eigen::Vector2d& k) { return (k - x).squaredNorm() <= merge2; }))
            continue;
        // The gap between the two bodies' surfaces above x: B's lowest minus A's highest point there
        // (a vertex's own height where x is a vertex: the line through it may miss its body by rounding).
        // Every candidate lies over both faces (the overlap) or over the other body's face (a
        // vertex): where a face turns towards the other body, the body's surface there is the
        // face's plane (convexity); otherwise the faces' half-spaces decide.
        const double on_b = !std::isnan(c.on_b) ? c.on_b
                            : b_faces        ? pieceHeight(pb, plane_b, x, mid, u, w, n)
                                             : surfaceHeight(b, pose_b, x, mid, u, w, n, -1.0);
        const double on_a = !std::isnan(c.on_a) ? c.on_a
                            : a_faces        ? pieceHeight(pa, plane_a, x, mid, u, w, n)
                                             : surfaceHeight(a, pose_a, x, mid, u, w, n, 1.0);
        const double gap = on_b - on_a;
        if (!std::isfinite(gap) || !(gap <= reach)) continue;
        kept.push_back(x);
        const Vec3 p = mid + x.x() * u + x.y() * w;
        patch.points.push_back(p);
        patch.gaps.push_back(gap);
        if (gap < tolerance) {
            touching_sum += p;
            ++touching;
        }
    }
    // The patch must hold the closest features: where the query finds the bodies closer (deeper)
    // than the patch's closest point by more than the tolerance, they are elsewhere, and the query's
    // closest point joins it. Nothing touching yet (a pair closing within reach), the patch's
    // centroid is then that point, else its closest one. A patch that touches but misses where the
    // bodies overlap (the faces the normal picked do not hold the penetrating corner) gets the
    // point among what touches, so the solve pushes where the overlap is. (In a turning drum, pairs
    // 1.4 cm deep had patches whose points all lay 0.3-1 mm apart, and sank a millimetre a frame.)
    if (patch.points.empty()) return;
    const auto deepest = std::min_element(patch.gaps.begin(), patch.gaps.end());
    const std::size_t closest = static_cast<std::size_t>(deepest - patch.gaps.begin());
    if (*deepest > result.distance + tolerance) {
        patch.points.push_back(mid);
        patch.gaps.push_back(result.distance);
        if (touching == 0) {
            patch.centroid = mid;
            return;
        }
        touching_sum += mid;
        ++touching;
    } else if (touching == 0) {
        patch.centroid = patch.points[closest];
        return;
    }
    patch.centroid = touching_sum / touching;
}

/// Reference and incident faces clipped, points kept within `reach` (see contactPatch), into the
/// empty `patch`; left empty when nothing touches.
void speculativePatch(const ConvexMesh& a, const Pose& pose_a, const ConvexMesh& b, const Pose& pose_b,
                      const FeatureCache& cache, const ProximityResult& result, double tolerance, double reach,
                      ContactPatch& patch) {
    const Vec3 n = result.normal;
    // Face normals turned to world once per body: a face borders several vertices.
    std::vector<Vec3>& normals_a = scratch().normals_a;
    std::vector<Vec3>& normals_b = scratch().normals_b;
    worldNormals(a, pose_a, normals_a);
    worldNormals(b, pose_b, normals_b);
    // Penetrating, the normal is the depth query's (MPR), not the walk's: the features the walk
    // stopped at need not border the faces that meet along it. (In a turning drum, two boxes 15 mm
    // into each other face to face kept a cached face at right angles to the normal: their faces
    // did not overlap, the patch was the one deepest point, and they sank for a third of a second.)
    // The faces that meet are then the two most aligned with the normal of all. So too where the
    // walk saw zero distance: the normal is then the best of both features' axes (proximity.cpp),
    // which may be a face of one body that the other's feature does not border (a cube set exactly
    // on two others took one point under each, and sank 0.7 mm in a tick).
    const bool any_face = result.penetrating || !(result.distance > 0.0);
    const int fa = alignedFace(a, normals_a, cache.a, n, any_face);
    const int fb = alignedFace(b, normals_b, cache.b, -n, any_face);
    if (fa < 0 || fb < 0) return;
    clipFaces(a, pose_a, b, pose_b, normals_a, normals_b, fa, fb, result, tolerance, reach, patch);
}

}  // namespace

ContactPatch contactPatch(const ConvexMesh& a, const Pose& pose_a, const ConvexMesh& b, const Pose& pose_b,
                          const FeatureCache& cache, const ProximityResult& result, double tolerance, double reach) {
    ContactPatch patch;
    contactPatch(a, pose_a, b, pose_b, cache, result, tolerance, reach, patch);
    return patch;
}

void contactPatch(const ConvexMesh& a, const Pose& pose_a, const ConvexMesh& b, const Pose& pose_b,
                  const FeatureCache& cache, const ProximityResult& result, double tolerance, double reach,
                  ContactPatch& patch) {
    patch.points.clear();
    patch.gaps.clear();
    patch.centroid = Vec3::Zero();
    const Vec3 n = result.normal;
    const Vec3 mid = 0.5 * (result.point_a + result.point_b);
    Vec3 u, w;
    planeBasis(n, u, w);
    auto to2 = [&](const Vec3& x) { return Eigen::Vector2d((x - mid).dot(u), (x - mid).dot(w)); };
    auto to3 = [&](const Eigen::Vector2d& x) { return Vec3(mid + x.x() * u + x.y() * w); };
    if (reach > tolerance) {
        speculativePatch(a, pose_a, b, pose_b, cache, result, tolerance, reach, patch);
        if (!patch.points.empty()) return;
        patch.centroid = Vec3::Zero();
    }
    Scratch& sc = scratch();
    std::vector<Vec3>& pa = sc.piece_a;
    std::vector<Vec3>& pb = sc.piece_b;
    // Where the walk saw zero distance its features need not border the faces that meet along the
    // normal (speculativePatch): a body's face most aligned with the normal is its piece's start if
    // it lies on the support plane. (Cubes set exactly on one another got an edge each.)
    Feature from_a = cache.a, from_b = cache.b;
    if (!result.penetrating && result.distance == 0.0) {
        auto onPlane = [&](const ConvexMesh& m, const Pose& pose, std::vector<Vec3>& normals, const Vec3& dir,
                           const Vec3& at, Feature& from) {
            worldNormals(m, pose, normals);
            const int face = alignedFace(m, normals, from, dir, true);   // of all faces: `from` unread
            if (face >= 0 && faceOnPlane(m, pose, face, dir, at, tolerance)) from = {FeatureType::Face, face};
        };
        onPlane(a, pose_a, sc.normals_a, n, result.point_a, from_a);
        onPlane(b, pose_b, sc.normals_b, -n, result.point_b, from_b);
    }
    supportPiece(a, pose_a, from_a, n, result.point_a, tolerance, pa);
    supportPiece(b, pose_b, from_b, -n, result.point_b, tolerance, pb);
    Poly2& a2 = sc.a2;
    Poly2& b2 = sc.b2;
    Poly2& out = sc.out;
    a2.clear();
    b2.clear();
    out.clear();
    for (const Vec3& x : pa) a2.push_back(to2(x));
    for (auto it = pb.rbegin(); it != pb.rend(); ++it) b2.push_back(to2(*it));   // B's CCW is about -n
    if (a2.size() >= 3 && b2.size() >= 3)
        clipPolygon(b2, a2, out);
    else if (a2.size() >= 3 && b2.size() == 2)
        clipSegment(b2[0], b2[1], a2, out);
    else if (b2.size() >= 3 && a2.size() == 2)
        clipSegment(a2[0], a2[1], b2, out);
    else if (a2.size() == 2 && b2.size() == 2) {   // parallel edges: overlap along a's direction
        const Eigen::Vector2d d = a2[1] - a2[0];
        if (std::abs(cross2(d.normalized(), b2[1] - b2[0])) <= tolerance) {
            const double dd = d.squaredNorm();
            const double t0 = (b2[0] - a2[0]).dot(d) / dd, t1 = (b2[1] - a2[0]).dot(d) / dd;
            const double lo = std::max(0.0, std::min(t0, t1)), hi = std::min(1.0, std::max(t0, t1));
            if (lo <= hi) out.assign({a2[0] + lo * d, a2[0] + hi * d});
        }
    }
    if (out.empty()) {
        patch.points.push_back(mid);
        patch.gaps.push_back(result.distance);
        patch.centroid = mid;
        return;
    }
    const PiecePlane plane_a = piecePlane(pa, n), plane_b = piecePlane(pb, n);
    double area = 0.0;
    Eigen::Vector2d c = Eigen::Vector2d::Zero(), mean = Eigen::Vector2d::Zero();
    for (size_t k = 0; k < out.size(); ++k) {
        const double cr = cross2(out[k], out[(k + 1) % out.size()]);
        area += cr;
        c += cr * (out[k] + out[(k + 1) % out.size()]);
        mean += out[k];
        patch.points.push_back(to3(out[k]));
        if (reach > tolerance)   // only speculative contact reads the gaps
            patch.gaps.push_back(pieceHeight(pb, plane_b, out[k], mid, u, w, n) -
                                 pieceHeight(pa, plane_a, out[k], mid, u, w, n));
    }
    mean /= static_cast<double>(out.size());
    // Area centroid for a polygon; the mean for a segment, a point or a degenerate sliver.
    const double scale2 = (out.front() - mean).squaredNorm() + 1e-300;
    patch.centroid = to3(out.size() >= 3 && std::abs(area) > 1e-12 * scale2 ? Eigen::Vector2d(c / (3.0 * area)) : mean);
}

}  // namespace vroc::native
