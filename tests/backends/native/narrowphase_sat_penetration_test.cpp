// SPDX-License-Identifier: MIT
// satPenetration (narrowphase/sat_penetration.h): the exact minimum translation distance of two
// overlapping convex polyhedra, against a closed form (two boxes), brute-force SAT over every face
// normal and edge pair (narrowphase_reference.h), and the definition (moving B by the depth along
// the normal leaves the two touching).
#include <gtest/gtest.h>

#include "narrowphase/sat_penetration.h"
#include "narrowphase_reference.h"

namespace vroc::native::testing {
namespace {

// The depth, normal and deepest points against brute force; "" or what is wrong.
std::string checkDepth(const ConvexPolyhedron& pa, const Pose& pose_a, const ConvexPolyhedron& pb, const Pose& pose_b,
                       double tol) {
    const WorldHull wa = toWorld(pa, pose_a), wb = toWorld(pb, pose_b);
    const SatResult ref = bruteForceSat(wa, wb);
    const ConvexMesh ma = ConvexMesh::fromPolyhedron(pa), mb = ConvexMesh::fromPolyhedron(pb);
    const SatPenetration r = satPenetration(ma, pose_a, mb, pose_b);
    std::string err;
    if (std::abs(r.depth + ref.separation) > tol)
        err += fmt::format("depth {:.17g}, brute-force SAT {:.17g}\n", r.depth, -ref.separation);
    if (std::abs(r.normal.norm() - 1.0) > 1e-12) err += "normal not unit\n";
    // Along the normal the two overlap by exactly the depth...
    double amax = -1e300, bmin = 1e300;
    for (const Vec3& v : wa.vertices) amax = std::max(amax, r.normal.dot(v));
    for (const Vec3& v : wb.vertices) bmin = std::min(bmin, r.normal.dot(v));
    if (std::abs((amax - bmin) - r.depth) > tol) err += fmt::format("overlap along the normal {:.17g}\n", amax - bmin);
    // ...so B moved by it touches A.
    Pose moved = pose_b;
    moved.position += r.depth * r.normal;
    const double after = bruteForceSat(wa, toWorld(pb, moved)).separation;
    if (std::abs(after) > tol) err += fmt::format("after moving B by depth * normal the separation is {:.3g}\n", after);
    if (((r.point_a - r.point_b) - r.depth * r.normal).norm() > tol) err += "point_a - point_b != depth * normal\n";
    // The deepest points lie on the bounding planes along the normal.
    if (std::abs(r.normal.dot(r.point_a) - amax) > tol) err += "point_a is not A's extreme along the normal\n";
    if (std::abs(r.normal.dot(r.point_b) - bmin) > tol) err += "point_b is not B's extreme along the normal\n";
    return err;
}

TEST(NarrowphaseSatPenetration, AxisAlignedBoxesOverlapByTheClosedForm) {
    // Box A (half extents 1, 2, 3) at the origin; box B (0.5, 0.5, 0.5) with its centre at x = 1.5 - d:
    // they overlap by d along x (the least of the three axes), normal +x.
    const ConvexMesh a = ConvexMesh::box(Vec3(1, 2, 3)), b = ConvexMesh::box(Vec3(0.5, 0.5, 0.5));
    for (double d : {1e-6, 1e-3, 0.1, 0.4}) {
        const SatPenetration r = satPenetration(a, Pose{}, b, Pose{Vec3(1.5 - d, 0.2, -0.7), Quat::Identity()});
        EXPECT_NEAR(r.depth, d, 1e-14) << d;
        EXPECT_NEAR((r.normal - Vec3::UnitX()).norm(), 0.0, 1e-14) << d;
        EXPECT_TRUE(r.axis == SatAxis::FaceA || r.axis == SatAxis::FaceB) << d;
    }
}

// Two boxes of a 400-box bin, 18 mm into each other edge on edge (the poses of seed 30002 at
// t = 2.52 s). libccd's MPR called this 18.5 mm along (0.11, 0.49, 0.87), along which they overlap
// by 32.5 mm; the exact answer is 18.29 mm along an edge-edge axis near (0.007, 0.416, 0.909).
TEST(NarrowphaseSatPenetration, DeepBoxPairOfABinIsExact) {
    const ConvexPolyhedron pa = ConvexPolyhedron::box(Vec3(0.080957, 0.097755, 0.0554489));
    const ConvexPolyhedron pb = ConvexPolyhedron::box(Vec3(0.0846049, 0.0778176, 0.0712903));
    const Pose pose_a{Vec3(0.078667533, 0.720940598, 0.262586087),
                      Quat(0.032778552, 0.085581562, 0.995455550, -0.025876848).normalized()};   // (w, x, y, z)
    const Pose pose_b{Vec3(0.113992367, 0.886296872, 0.366339372),
                      Quat(-0.161385414, -0.636116967, -0.142134972, -0.741017950).normalized()};
    EXPECT_EQ(checkDepth(pa, pose_a, pb, pose_b, 1e-12), "");
    const SatPenetration r = satPenetration(ConvexMesh::fromPolyhedron(pa), pose_a, ConvexMesh::fromPolyhedron(pb), pose_b);
    EXPECT_NEAR(r.depth, 0.01829, 1e-5);
    EXPECT_EQ(r.axis, SatAxis::EdgeEdge);
}

// Random hulls of 4-40 vertices, overlapping by up to most of their size, at 1 mm, 1 m and 1 km.
TEST(NarrowphaseSatPenetration, RandomHullPairsMatchBruteForce) {
    std::mt19937_64 rng(20261206);
    std::uniform_int_distribution<int> vertices(4, 40);
    std::uniform_real_distribution<double> unit(-1.0, 1.0), spread(0.0, 1.2);
    int overlapping = 0, edge_axes = 0;
    for (double scale : {1e-3, 1.0, 1e3}) {
        for (int trial = 0; trial < 1500; ++trial) {
            const ConvexPolyhedron pa = randomHull(rng, vertices(rng), scale), pb = randomHull(rng, vertices(rng), scale);
            const Pose pose_a{Vec3(unit(rng), unit(rng), unit(rng)) * scale, randomRotation(rng)};
            const Pose pose_b{pose_a.position + Vec3(unit(rng), unit(rng), unit(rng)).normalized() * spread(rng) * scale,
                              randomRotation(rng)};
            if (!(bruteForceSat(toWorld(pa, pose_a), toWorld(pb, pose_b)).separation < -1e-9 * scale)) continue;
            ++overlapping;
            const std::string err = checkDepth(pa, pose_a, pb, pose_b, 1e-9 * scale);
            ASSERT_EQ(err, "") << "scale " << scale << ", trial " << trial << "\n"
                               << regressionTest(fmt::format("Sat{}", trial), pa, pose_a, pb, pose_b);
            edge_axes += satPenetration(ConvexMesh::fromPolyhedron(pa), pose_a, ConvexMesh::fromPolyhedron(pb), pose_b)
                             .axis == SatAxis::EdgeEdge;
        }
    }
    EXPECT_GT(overlapping, 2000);
    EXPECT_GT(edge_axes, 100);   // the edge-edge axes are exercised, not only faces
}

}  // namespace
}  // namespace vroc::native::testing
