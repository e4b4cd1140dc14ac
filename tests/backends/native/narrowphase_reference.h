// SPDX-License-Identifier: MIT
// Test-only references for the native narrow phase, independent of the library's walk:
//  - brute-force distance over every feature pair (vertex-face, face-vertex, edge-edge; the
//    edge-edge pairs cover vertex-vertex and vertex-edge), in world coordinates, from the
//    ConvexPolyhedron (not the half-edge mesh);
//  - brute-force SAT (all face normals and edge-pair cross products): the overlap verdict and
//    the exact minimum penetration depth;
//  - libccd GJK/MPR with linear-scan support functions;
//  - random hulls and poses, and a printer that turns a failing case into a C++ regression test.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <ccd/ccd.h>
#include <fmt/format.h>

#include "vroc/core/convex_polyhedron.h"
#include "vroc/core/math.h"

namespace vroc::native::testing {

struct WorldHull {
    std::vector<Vec3> vertices;                 // world
    std::vector<std::vector<int>> faces;        // CCW from outside
    std::vector<Vec3> normals;                  // world, unit
    std::vector<std::pair<int, int>> edges;     // undirected, each once
};

inline WorldHull toWorld(const ConvexPolyhedron& p, const Pose& pose) {
    WorldHull h;
    for (const Vec3& v : p.vertices) h.vertices.push_back(pose.apply(v));
    h.faces = p.faces;
    for (const Vec3& n : p.face_normals) h.normals.push_back(pose.rotate(n));
    for (const auto& f : p.faces)
        for (size_t k = 0; k < f.size(); ++k) {
            const int a = f[k], b = f[(k + 1) % f.size()];
            if (a < b) h.edges.emplace_back(a, b);
        }
    return h;
}

struct Closest {
    double distance = std::numeric_limits<double>::infinity();
    Vec3 pa = Vec3::Zero(), pb = Vec3::Zero();
};

/// Point to segment, exact (clamped projection).
inline Vec3 nearestOnSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 d = b - a;
    const double t = d.squaredNorm() > 0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    return a + t * d;
}

/// Segment-segment: the interior stationary point if it lies in [0,1]^2, else the best of the
/// four boundary pieces (endpoint against the other segment). Convex quadratic: exact.
inline void segmentSegment(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1, Closest& best) {
    auto offer = [&](const Vec3& x, const Vec3& y) {
        const double d = (x - y).norm();
        if (d < best.distance) best = {d, x, y};
    };
    offer(p0, nearestOnSegment(p0, q0, q1));
    offer(p1, nearestOnSegment(p1, q0, q1));
    offer(nearestOnSegment(q0, p0, p1), q0);
    offer(nearestOnSegment(q1, p0, p1), q1);
    const Vec3 u = p1 - p0, v = q1 - q0, w = p0 - q0;
    const double a = u.dot(u), b = u.dot(v), c = v.dot(v), d = u.dot(w), e = v.dot(w);
    const double det = a * c - b * b;
    if (det <= 1e-300) return;
    const double s = (b * e - c * d) / det, t = (a * e - b * d) / det;
    if (s >= 0 && s <= 1 && t >= 0 && t <= 1) offer(p0 + s * u, q0 + t * v);
}

/// Vertices p of one hull against the faces of the other, when p projects inside the face.
inline void vertexFaces(const WorldHull& points, const WorldHull& faces, bool points_are_a, Closest& best) {
    for (size_t f = 0; f < faces.faces.size(); ++f) {
        const auto& ids = faces.faces[f];
        const Vec3& n = faces.normals[f];
        const Vec3& o = faces.vertices[ids[0]];
        for (const Vec3& p : points.vertices) {
            const double h = n.dot(p - o);
            if (h < 0) continue;   // under the plane: not a separated closest pair through this face
            const Vec3 q = p - h * n;
            bool inside = true;
            for (size_t k = 0; k < ids.size() && inside; ++k) {
                const Vec3& a = faces.vertices[ids[k]];
                const Vec3& b = faces.vertices[ids[(k + 1) % ids.size()]];
                inside = (b - a).cross(q - a).dot(n) >= 0;
            }
            if (inside && h < best.distance) best = points_are_a ? Closest{h, p, q} : Closest{h, q, p};
        }
    }
}

/// Brute-force distance of two separated hulls (meaningless when they overlap: check SAT first).
inline Closest bruteForceDistance(const WorldHull& a, const WorldHull& b) {
    Closest best;
    vertexFaces(a, b, true, best);
    vertexFaces(b, a, false, best);
    for (const auto& ea : a.edges)
        for (const auto& eb : b.edges)
            segmentSegment(a.vertices[ea.first], a.vertices[ea.second], b.vertices[eb.first], b.vertices[eb.second], best);
    return best;
}

/// Brute-force SAT: the largest separation over all candidate axes (> 0 apart, < 0 overlapping;
/// for overlapping convex polytopes, minus the exact minimum penetration depth) and its axis (A->B).
struct SatResult {
    double separation = -std::numeric_limits<double>::infinity();
    Vec3 axis = Vec3::UnitX();
};

inline SatResult bruteForceSat(const WorldHull& a, const WorldHull& b) {
    SatResult r;
    auto test = [&](Vec3 axis) {
        const double len = axis.norm();
        if (len < 1e-12) return;
        axis /= len;
        double amin = 1e300, amax = -1e300, bmin = 1e300, bmax = -1e300;
        for (const Vec3& v : a.vertices) { amin = std::min(amin, axis.dot(v)); amax = std::max(amax, axis.dot(v)); }
        for (const Vec3& v : b.vertices) { bmin = std::min(bmin, axis.dot(v)); bmax = std::max(bmax, axis.dot(v)); }
        const double s1 = bmin - amax, s2 = amin - bmax;
        if (s1 >= s2 && s1 > r.separation) r = {s1, axis};
        if (s2 > s1 && s2 > r.separation) r = {s2, -axis};
    };
    for (const Vec3& n : a.normals) test(n);
    for (const Vec3& n : b.normals) test(n);
    for (const auto& ea : a.edges)
        for (const auto& eb : b.edges)
            test((a.vertices[ea.second] - a.vertices[ea.first]).normalized().cross(
                (b.vertices[eb.second] - b.vertices[eb.first]).normalized()));
    return r;
}

/// Signed distance of x to the hull (max over face planes): ~0 on the surface.
inline double surfaceDistance(const WorldHull& h, const Vec3& x) {
    double d = -1e300;
    for (size_t f = 0; f < h.faces.size(); ++f) d = std::max(d, h.normals[f].dot(x - h.vertices[h.faces[f][0]]));
    return d;
}

// ---- libccd with linear-scan supports (independent of the mesh's hill climbing) ----
inline void ccdSupport(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* out) {
    const auto* h = static_cast<const WorldHull*>(obj);
    const Vec3 d(dir->v[0], dir->v[1], dir->v[2]);
    size_t best = 0;
    for (size_t i = 1; i < h->vertices.size(); ++i)
        if (d.dot(h->vertices[i]) > d.dot(h->vertices[best])) best = i;
    ccdVec3Set(out, h->vertices[best].x(), h->vertices[best].y(), h->vertices[best].z());
}
inline void ccdCenter(const void* obj, ccd_vec3_t* out) {
    const auto* h = static_cast<const WorldHull*>(obj);
    Vec3 c = Vec3::Zero();
    for (const Vec3& v : h->vertices) c += v;
    c /= static_cast<double>(h->vertices.size());
    ccdVec3Set(out, c.x(), c.y(), c.z());
}
inline ccd_t ccdSetup(double tolerance) {
    ccd_t ccd;
    CCD_INIT(&ccd);
    ccd.support1 = ccd.support2 = ccdSupport;
    ccd.center1 = ccd.center2 = ccdCenter;
    ccd.max_iterations = 500;
    ccd.mpr_tolerance = tolerance;
    ccd.epa_tolerance = tolerance;
    return ccd;
}

// ---- random shapes and poses ----
inline ConvexPolyhedron randomHull(std::mt19937_64& rng, int n, double scale, double squash = 1.0) {
    std::normal_distribution<double> g;
    std::vector<Vec3> pts;
    for (int i = 0; i < n; ++i) {
        Vec3 v(g(rng), g(rng), g(rng));
        v = v.normalized() * scale;
        v.z() *= squash;
        pts.push_back(v);
    }
    return ConvexPolyhedron::fromPoints(pts);
}

inline Quat randomRotation(std::mt19937_64& rng) {
    std::normal_distribution<double> g;
    return Quat(g(rng), g(rng), g(rng), g(rng)).normalized();
}

// ---- regression printer (fcl style: paste into a TEST body) ----
inline std::string cppVec(const Vec3& v) { return fmt::format("Vec3({:.17g}, {:.17g}, {:.17g})", v.x(), v.y(), v.z()); }
inline std::string cppQuat(const Quat& q) { return fmt::format("Quat({:.17g}, {:.17g}, {:.17g}, {:.17g})", q.w(), q.x(), q.y(), q.z()); }

inline std::string regressionTest(const std::string& name, const ConvexPolyhedron& a, const Pose& pa,
                                  const ConvexPolyhedron& b, const Pose& pb) {
    std::ostringstream s;
    s << "\n// ---- paste into a *_test.cpp (uses narrowphase_reference.h) ----\n"
      << "TEST(NarrowphaseRegression, " << name << ") {\n  const std::vector<Vec3> pa{";
    for (const Vec3& v : a.vertices) s << cppVec(v) << ", ";
    s << "};\n  const std::vector<Vec3> pb{";
    for (const Vec3& v : b.vertices) s << cppVec(v) << ", ";
    s << "};\n  Pose pose_a{" << cppVec(pa.position) << ", " << cppQuat(pa.orientation) << "};\n"
      << "  Pose pose_b{" << cppVec(pb.position) << ", " << cppQuat(pb.orientation) << "};\n"
      << "  expectAgreesWithReference(ConvexPolyhedron::fromPoints(pa), pose_a, ConvexPolyhedron::fromPoints(pb), pose_b);\n}\n";
    return s.str();
}

}  // namespace vroc::native::testing
