// SPDX-License-Identifier: MIT
// ConvexPolyhedron::fromPoints against independent answers: known solids, a brute-force facet
// enumeration, and point-in-hull / extremality checks done here without the library's own validator.
// A failing case prints its input as a C++ initializer list, ready to paste into a regression test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "../../core/src/polyhedron_checks.h"   // internal validator, tested directly below
#include "vroc/core/convex_polyhedron.h"
#include "vroc/core/errors.h"

namespace vroc {
namespace {

using Points = std::vector<Vec3>;

/// The input as `Points pts = {{x, y, z}, ...};` with round-trip precision.
std::string pasteable(const Points& pts) {
    std::string s = "Points pts = {";
    char buf[128];
    for (const Vec3& p : pts) {
        std::snprintf(buf, sizeof buf, "{%.17g, %.17g, %.17g}, ", p.x(), p.y(), p.z());
        s += buf;
    }
    return s + "};";
}

Points cubeCorners(double h) {
    Points pts;
    for (int i = 0; i < 8; ++i) pts.emplace_back((i & 1) ? h : -h, (i & 2) ? h : -h, (i & 4) ? h : -h);
    return pts;
}

/// Points on an n x n grid on each face of the cube [-h, h]^3 (corners, edge and face points).
Points subdividedCube(double h, int n) {
    Points pts;
    for (int axis = 0; axis < 3; ++axis)
        for (double side : {-h, h})
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) {
                    Vec3 p;
                    p[axis] = side;
                    p[(axis + 1) % 3] = -h + 2 * h * i / (n - 1);
                    p[(axis + 2) % 3] = -h + 2 * h * j / (n - 1);
                    pts.push_back(p);
                }
    return pts;
}

Points randomCloud(std::mt19937_64& rng, int n) {
    std::normal_distribution<double> g(0.0, 1.0);
    Points pts;
    for (int i = 0; i < n; ++i) pts.emplace_back(g(rng), 0.5 * g(rng), 2.0 * g(rng));
    return pts;
}

Vec3 polygonNormal(const ConvexPolyhedron& p, const std::vector<int>& face) {
    Vec3 n = Vec3::Zero();
    for (size_t k = 0; k < face.size(); ++k) n += p.vertices[face[k]].cross(p.vertices[face[(k + 1) % face.size()]]);
    return n;
}

/// Independent checks of a hull of `pts`: all points inside, faces planar / CCW / outward,
/// vertices are input points and extreme, Euler characteristic 2.
void expectValidHullOf(const ConvexPolyhedron& p, const Points& pts, double tol) {
    SCOPED_TRACE(pasteable(pts));
    ASSERT_EQ(p.faces.size(), p.face_normals.size());
    ASSERT_EQ(p.faces.size(), p.face_offsets.size());
    EXPECT_EQ(static_cast<int>(p.vertices.size()) - p.edgeCount() + static_cast<int>(p.faces.size()), 2);
    for (size_t f = 0; f < p.faces.size(); ++f) {
        const Vec3& n = p.face_normals[f];
        EXPECT_NEAR(n.norm(), 1.0, 1e-12);
        EXPECT_GT(polygonNormal(p, p.faces[f]).normalized().dot(n), 1.0 - 1e-9) << "face " << f << " not CCW";
        for (int v : p.faces[f]) EXPECT_NEAR(n.dot(p.vertices[v]), p.face_offsets[f], tol) << "face " << f;
        for (size_t i = 0; i < pts.size(); ++i)
            ASSERT_LE(n.dot(pts[i]) - p.face_offsets[f], tol) << "input point " << i << " outside face " << f;
    }
    for (size_t v = 0; v < p.vertices.size(); ++v) {
        EXPECT_NE(std::find(pts.begin(), pts.end(), p.vertices[v]), pts.end()) << "vertex " << v << " not an input";
        Vec3 witness = Vec3::Zero();   // sum of incident face normals: a supporting direction
        for (size_t f = 0; f < p.faces.size(); ++f)
            if (std::count(p.faces[f].begin(), p.faces[f].end(), static_cast<int>(v))) witness += p.face_normals[f];
        for (const Vec3& q : pts) {
            if (q == p.vertices[v]) continue;
            EXPECT_LT(witness.dot(q - p.vertices[v]), 0.0) << "vertex " << v << " not extreme";
        }
    }
}

TEST(ConvexPolyhedron, CubeCornersWithInteriorPointsGivesEightVerticesSixQuads) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-0.99, 0.99);
    Points pts = cubeCorners(1.0);
    for (int i = 0; i < 300; ++i) pts.emplace_back(u(rng), u(rng), u(rng));
    std::shuffle(pts.begin(), pts.end(), rng);
    const ConvexPolyhedron p = ConvexPolyhedron::fromPoints(pts);
    ASSERT_EQ(p.vertices.size(), 8u) << pasteable(pts);
    ASSERT_EQ(p.faces.size(), 6u);
    EXPECT_EQ(p.edgeCount(), 12);
    for (const auto& f : p.faces) EXPECT_EQ(f.size(), 4u);
    for (const Vec3& v : p.vertices) EXPECT_EQ(v.cwiseAbs(), Vec3(1, 1, 1));
    for (size_t f = 0; f < 6; ++f) {
        EXPECT_NEAR(p.face_normals[f].cwiseAbs().maxCoeff(), 1.0, 1e-15);
        EXPECT_NEAR(p.face_offsets[f], 1.0, 1e-15);
    }
    EXPECT_DOUBLE_EQ(p.boundingRadius(), std::sqrt(3.0));
    expectValidHullOf(p, pts, 1e-12);
}

TEST(ConvexPolyhedron, SubdividedCubeFacesMergeIntoSixFaces) {
    const Points pts = subdividedCube(0.5, 7);   // 294 points, many coplanar and mid-edge
    const ConvexPolyhedron p = ConvexPolyhedron::fromPoints(pts);
    EXPECT_EQ(p.vertices.size(), 8u) << pasteable(pts);
    EXPECT_EQ(p.faces.size(), 6u);
    EXPECT_EQ(p.edgeCount(), 12);
    expectValidHullOf(p, pts, 1e-12);
}

TEST(ConvexPolyhedron, RotatedOffsetSubdividedCubeStillSixFaces) {
    // Rotation and a far offset round the coplanar points off their planes by ~1e-16 relative.
    const Quat q = Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized())).normalized();
    const Vec3 offset(1000.0, -250.0, 40.0);
    Points pts = subdividedCube(0.3, 9);
    for (Vec3& p : pts) p = q * p + offset;
    const ConvexPolyhedron p = ConvexPolyhedron::fromPoints(pts);
    EXPECT_EQ(p.vertices.size(), 8u) << pasteable(pts);
    EXPECT_EQ(p.faces.size(), 6u);
    for (const auto& f : p.faces) EXPECT_EQ(f.size(), 4u);
    expectValidHullOf(p, pts, 1e-9);
}

/// Subdivided cube whose non-corner points move by up to +-`jitter` [m] along their face normal.
Points jitteredCube(double jitter, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-jitter, jitter);
    Points pts = subdividedCube(1.0, 6);
    for (Vec3& p : pts)
        if (p.cwiseAbs().minCoeff() < 1.0) {   // not a corner
            int axis;
            p.cwiseAbs().maxCoeff(&axis);
            p[axis] += u(rng);
        }
    return pts;
}

TEST(ConvexPolyhedron, NearlyCoplanarPointsMergeOnlyWithinTheTightTolerance) {
    std::mt19937_64 rng(11);
    // 1e-12 m on a 3.5 m hull is far below the merge distance (1e-9 x diagonal): six faces.
    const Points fine = jitteredCube(1e-12, rng);
    const ConvexPolyhedron p = ConvexPolyhedron::fromPoints(fine);
    EXPECT_EQ(p.faces.size(), 6u) << pasteable(fine);
    expectValidHullOf(p, fine, 1e-11);
    // 1e-4 m is a real shape change: the faces must not be flattened. Facets that happen to be
    // within the merge distance still merge, so points may stick out by up to the documented
    // 1e-8 x diagonal.
    const Points coarse = jitteredCube(1e-4, rng);
    const ConvexPolyhedron q = ConvexPolyhedron::fromPoints(coarse);
    EXPECT_GT(q.faces.size(), 30u) << pasteable(coarse);
    expectValidHullOf(q, coarse, 1e-8 * 2.0 * std::sqrt(3.0));
}

TEST(ConvexPolyhedron, OctahedronAndSquarePyramidHaveTheirFaces) {
    const Points octa = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0.1, 0.2, 0.3}};
    const ConvexPolyhedron o = ConvexPolyhedron::fromPoints(octa);
    EXPECT_EQ(o.vertices.size(), 6u);
    EXPECT_EQ(o.faces.size(), 8u);
    EXPECT_EQ(o.edgeCount(), 12);
    for (size_t f = 0; f < o.faces.size(); ++f) EXPECT_NEAR(o.face_offsets[f], 1.0 / std::sqrt(3.0), 1e-15);
    expectValidHullOf(o, octa, 1e-12);

    // Square base with its centre and edge midpoints as extra (coplanar / collinear) points.
    const Points pyramid = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {0, 0, 0}, {0, -1, 0}, {1, 0, 0}, {0, 0, 2}};
    const ConvexPolyhedron py = ConvexPolyhedron::fromPoints(pyramid);
    EXPECT_EQ(py.vertices.size(), 5u);
    ASSERT_EQ(py.faces.size(), 5u);
    int quads = 0;
    for (size_t f = 0; f < py.faces.size(); ++f)
        if (py.faces[f].size() == 4) {
            ++quads;
            EXPECT_EQ(py.face_normals[f], Vec3(0, 0, -1));
            EXPECT_EQ(py.face_offsets[f], 0.0);
        }
    EXPECT_EQ(quads, 1);
    expectValidHullOf(py, pyramid, 1e-12);
}

TEST(ConvexPolyhedron, RandomCloudsContainEveryPointAndAreConvex) {
    for (int seed = 0; seed < 25; ++seed) {
        std::mt19937_64 rng(1000 + seed);
        const Points pts = randomCloud(rng, 20 + 15 * seed);
        const ConvexPolyhedron p = ConvexPolyhedron::fromPoints(pts);
        expectValidHullOf(p, pts, 1e-12);
    }
}

bool lexLess(const Vec3& a, const Vec3& b) { return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3); }
using VertexSet = std::set<Vec3, bool (*)(const Vec3&, const Vec3&)>;

std::set<std::vector<double>> facetKeys(const std::vector<VertexSet>& facets) {
    std::set<std::vector<double>> keys;
    for (const auto& f : facets) {
        std::vector<double> key;
        for (const Vec3& v : f) key.insert(key.end(), {v.x(), v.y(), v.z()});
        keys.insert(key);
    }
    return keys;
}

/// Brute force: in general position the hull's faces are exactly the triangles (i, j, k) with every
/// other point strictly on one side of their plane.
std::vector<VertexSet> bruteForceTriangles(const Points& pts) {
    std::vector<VertexSet> out;
    const size_t n = pts.size();
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 1; j < n; ++j)
            for (size_t k = j + 1; k < n; ++k) {
                const Vec3 normal = (pts[j] - pts[i]).cross(pts[k] - pts[i]);
                int above = 0, below = 0;
                for (size_t m = 0; m < n; ++m) {
                    if (m == i || m == j || m == k) continue;
                    (normal.dot(pts[m] - pts[i]) > 0 ? above : below)++;
                }
                if (above == 0 || below == 0) out.push_back(VertexSet({pts[i], pts[j], pts[k]}, lexLess));
            }
    return out;
}

TEST(ConvexPolyhedron, RandomCloudMatchesBruteForceFacets) {
    for (int seed = 0; seed < 5; ++seed) {
        std::mt19937_64 rng(77 + seed);
        const Points pts = randomCloud(rng, 30);
        const ConvexPolyhedron p = ConvexPolyhedron::fromPoints(pts);
        std::vector<VertexSet> ours;
        for (const auto& f : p.faces) {
            VertexSet s(lexLess);
            for (int v : f) s.insert(p.vertices[v]);
            ours.push_back(s);
        }
        EXPECT_EQ(facetKeys(ours), facetKeys(bruteForceTriangles(pts))) << pasteable(pts);
    }
}

TEST(ConvexPolyhedron, ResultDoesNotDependOnInputOrder) {
    std::mt19937_64 rng(5);
    Points pts = randomCloud(rng, 200);
    const ConvexPolyhedron a = ConvexPolyhedron::fromPoints(pts);
    std::shuffle(pts.begin(), pts.end(), rng);
    const ConvexPolyhedron b = ConvexPolyhedron::fromPoints(pts);
    auto sorted = [](Points v) { std::sort(v.begin(), v.end(), lexLess); return v; };
    EXPECT_EQ(sorted(a.vertices), sorted(b.vertices));
    EXPECT_EQ(a.faces.size(), b.faces.size());
    EXPECT_EQ(a.edgeCount(), b.edgeCount());
    const ConvexPolyhedron c = ConvexPolyhedron::fromPoints(pts);   // same input twice: identical
    EXPECT_EQ(b.vertices, c.vertices);
    EXPECT_EQ(b.faces, c.faces);
    EXPECT_EQ(b.face_offsets, c.face_offsets);
}

void expectRejected(const Points& pts, const std::string& words) {
    testing::internal::CaptureStdout();
    testing::internal::CaptureStderr();
    std::string message;
    try {
        ConvexPolyhedron::fromPoints(pts);
    } catch (const GeometryError& e) {
        message = e.what();
    }
    const std::string out = testing::internal::GetCapturedStdout();
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_NE(message.find(words), std::string::npos) << "message: '" << message << "'\n" << pasteable(pts);
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(out, "") << "qhull wrote to stdout";
    EXPECT_EQ(err, "") << "qhull wrote to stderr";
}

TEST(ConvexPolyhedron, DegenerateInputIsRejectedQuietly) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    expectRejected({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, "at least 4 points");
    expectRejected({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, "degenerate");
    expectRejected({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}}, "degenerate");
    expectRejected({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, nan}}, "not finite");
    expectRejected({{0, 0, 0}, {inf, 0, 0}, {0, 1, 0}, {0, 0, 1}}, "not finite");
    expectRejected({{1, 2, 3}, {1, 2, 3}, {1, 2, 3}, {1, 2, 3}}, "coincide");
    Points plane;   // many points on a tilted plane
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int i = 0; i < 100; ++i) {
        double x = u(rng), y = u(rng);
        plane.emplace_back(x, y, 0.3 * x - 0.2 * y + 5.0);
    }
    expectRejected(plane, "degenerate");
    Points sliver = cubeCorners(1.0);   // a 1e-12 m thin slab
    for (Vec3& p : sliver) p.z() *= 1e-12;
    expectRejected(sliver, "degenerate");
}

TEST(ConvexPolyhedron, BoxMatchesHullOfItsCorners) {
    const Vec3 h(0.5, 1.5, 0.25);
    const ConvexPolyhedron box = ConvexPolyhedron::box(h);
    Points corners = box.vertices;
    const ConvexPolyhedron hull = ConvexPolyhedron::fromPoints(corners);
    expectValidHullOf(box, corners, 1e-15);
    expectValidHullOf(hull, corners, 1e-15);
    EXPECT_EQ(box.edgeCount(), 12);
    EXPECT_DOUBLE_EQ(box.boundingRadius(), h.norm());
    auto sorted = [](Points v) { std::sort(v.begin(), v.end(), lexLess); return v; };
    EXPECT_EQ(sorted(box.vertices), sorted(hull.vertices));
}

TEST(ConvexPolyhedron, ManyPointsOnASphereStayValid) {
    Points pts;
    const int n = 2000;   // Fibonacci sphere: near-uniform, every point is a vertex
    const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < n; ++i) {
        const double z = 1.0 - 2.0 * (i + 0.5) / n, r = std::sqrt(1.0 - z * z);
        pts.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
    }
    const ConvexPolyhedron p = ConvexPolyhedron::fromPoints(pts);
    EXPECT_EQ(p.vertices.size(), static_cast<size_t>(n));
    EXPECT_NEAR(p.boundingRadius(), 1.0, 1e-15);
    expectValidHullOf(p, pts, 1e-12);
}

void refitPlanes(ConvexPolyhedron& p) {
    for (size_t f = 0; f < p.faces.size(); ++f) {
        p.face_normals[f] = polygonNormal(p, p.faces[f]).normalized();
        p.face_offsets[f] = p.face_normals[f].dot(p.vertices[p.faces[f][0]]);
    }
}

TEST(PolyhedronValidator, AcceptsValidAndNamesEachDefect) {
    using detail::checkPolyhedron;
    const Points octa_pts = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const ConvexPolyhedron octa = ConvexPolyhedron::fromPoints(octa_pts);
    EXPECT_EQ(checkPolyhedron(octa, 1e-12), "");
    EXPECT_EQ(checkPolyhedron(octa, 1e-12, 0.0), "");   // local convexity test
    EXPECT_EQ(checkPolyhedron(ConvexPolyhedron::box(Vec3(1, 2, 3)), 1e-12), "");

    ConvexPolyhedron dented = octa;   // top apex pushed through to z = -0.5: closed but not convex
    for (Vec3& v : dented.vertices)
        if (v.z() == 1.0) v.z() = -0.5;
    refitPlanes(dented);
    EXPECT_NE(checkPolyhedron(dented, 1e-12).find("not convex"), std::string::npos);
    EXPECT_NE(checkPolyhedron(dented, 1e-12, 0.0).find("not convex"), std::string::npos);

    ConvexPolyhedron warped = ConvexPolyhedron::box(Vec3(1, 1, 1));   // one corner lifted 1e-6
    warped.vertices[7] += Vec3(0, 0, 1e-6);
    EXPECT_NE(checkPolyhedron(warped, 1e-9).find("not planar"), std::string::npos);
    EXPECT_EQ(checkPolyhedron(warped, 1e-5), "");

    ConvexPolyhedron open = octa;   // a missing face leaves a hole
    open.faces.pop_back();
    open.face_normals.pop_back();
    open.face_offsets.pop_back();
    EXPECT_NE(checkPolyhedron(open, 1e-12).find("not closed"), std::string::npos);

    ConvexPolyhedron flipped = octa;   // one face wound the wrong way
    std::reverse(flipped.faces[0].begin(), flipped.faces[0].end());
    EXPECT_NE(checkPolyhedron(flipped, 1e-12).find("oriented"), std::string::npos);
}

}  // namespace
}  // namespace vroc
