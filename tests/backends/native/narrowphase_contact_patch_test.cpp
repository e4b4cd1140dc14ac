// SPDX-License-Identifier: MIT
// contactPatch against closed forms: face-face overlap rectangle, edge on face, vertex contact; and
// against brute-force SAT: a speculative patch of two overlapping boxes reaches where they overlap.
#include <array>

#include "narrowphase/contact_patch.h"
#include "narrowphase_check.h"

namespace vroc::native::testing {
namespace {

TEST(NarrowphaseContactPatch, StackedBoxesGiveTheOverlapRectangle) {
    const ConvexMesh a = ConvexMesh::box(Vec3(1, 1, 0.5)), b = ConvexMesh::box(Vec3(0.5, 0.5, 0.5));
    const Pose pb{Vec3(0.8, 0.2, 1.0 + 1e-5), Quat::Identity()};
    FeatureCache cache;
    const ProximityResult r = queryMeshMesh(a, Pose{}, b, pb, cache);
    const ContactPatch patch = contactPatch(a, Pose{}, b, pb, cache, r, 1e-4);
    // Overlap of [-1,1]x[-1,1] and [0.3,1.3]x[-0.3,0.7]: [0.3,1]x[-0.3,0.7], centroid (0.65, 0.2).
    ASSERT_EQ(patch.points.size(), 4u);
    EXPECT_NEAR((patch.centroid - Vec3(0.65, 0.2, 0.5 + 5e-6)).norm(), 0.0, 1e-12);
}

TEST(NarrowphaseContactPatch, EdgeOnFaceGivesTheClippedSegment) {
    const ConvexMesh a = ConvexMesh::box(Vec3(1, 1, 0.5)), b = ConvexMesh::box(Vec3(0.5, 0.5, 0.5));
    const Pose pb{Vec3(0.9, 0.0, 0.5 + 0.5 * std::sqrt(2.0) + 1e-6), Quat(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitY()))};
    FeatureCache cache;
    const ProximityResult r = queryMeshMesh(a, Pose{}, b, pb, cache);
    const ContactPatch patch = contactPatch(a, Pose{}, b, pb, cache, r, 1e-4);
    // B's lowest edge runs along y from -0.5 to 0.5 at x = 0.9: inside A's top face entirely.
    ASSERT_EQ(patch.points.size(), 2u);
    EXPECT_NEAR((patch.centroid - Vec3(0.9, 0.0, 0.5 + 5e-7)).norm(), 0.0, 1e-9);
    EXPECT_NEAR(std::abs(patch.points[0].y() - patch.points[1].y()), 1.0, 1e-9);
}

TEST(NarrowphaseContactPatch, VertexContactIsOnePoint) {
    const ConvexMesh a = ConvexMesh::box(Vec3(1, 1, 0.5)), b = ConvexMesh::box(Vec3(0.5, 0.5, 0.5));
    const Quat q = Quat::FromTwoVectors(Vec3(-1, -1, -1).normalized(), -Vec3::UnitZ());
    const Pose pb{Vec3(0.1, 0.2, 0.5 + 0.5 * std::sqrt(3.0) + 1e-6), q};
    FeatureCache cache;
    const ProximityResult r = queryMeshMesh(a, Pose{}, b, pb, cache);
    const ContactPatch patch = contactPatch(a, Pose{}, b, pb, cache, r, 1e-4);
    ASSERT_EQ(patch.points.size(), 1u);
    EXPECT_NEAR((patch.centroid - Vec3(0.1, 0.2, 0.5 + 5e-7)).norm(), 0.0, 1e-9);
}

TEST(NarrowphaseContactPatch, SpeculativeReachAddsTheTippingFaceWithItsGaps) {
    // A box tilted by theta about y rests on its lowest edge (x = -0.5 side) 0.5 mm above A's top
    // face. The vertices of its bottom face beyond the edge are 2 hx sin(theta) higher, those of the
    // side face beyond the same edge 2 hz sin(90 deg - theta)... and the reach decides which enter.
    const ConvexMesh a = ConvexMesh::box(Vec3(2, 2, 0.5)), b = ConvexMesh::box(Vec3(0.5, 0.3, 0.2));
    const double theta = 0.02, gap = 5e-4;
    const Quat q(Eigen::AngleAxisd(theta, Vec3::UnitY()));
    // Lowest point of the rotated box: the edge at local (-0.5, *, -0.2) for a small positive theta
    // about y (x = -0.5 goes down by 0.5 sin(theta), z = -0.2 by 0.2 cos(theta)).
    const double drop = 0.5 * std::sin(theta) + 0.2 * std::cos(theta);
    const Pose pb{Vec3(0.1, 0.0, 0.5 + drop + gap), q};
    FeatureCache cache;
    const ProximityResult r = queryMeshMesh(a, Pose{}, b, pb, cache);
    ASSERT_NEAR(r.distance, gap, 1e-12);
    const double far = gap + 1.0 * std::sin(theta);   // the bottom face's other edge: 2 hx sin(theta)
    // Without a reach: only the touching edge (2 points).
    const ContactPatch plain = contactPatch(a, Pose{}, b, pb, cache, r, 1e-3);
    EXPECT_EQ(plain.points.size(), 2u);
    // A reach past the far edge: the whole bottom face, with each corner's own gap.
    const ContactPatch spec = contactPatch(a, Pose{}, b, pb, cache, r, 1e-3, far + 1e-3);
    ASSERT_EQ(spec.points.size(), 4u);
    ASSERT_EQ(spec.gaps.size(), 4u);
    int near = 0, farther = 0;
    for (double g : spec.gaps) {
        if (std::abs(g - gap) < 1e-9) ++near;
        if (std::abs(g - far) < 1e-9) ++farther;
    }
    EXPECT_EQ(near, 2);
    EXPECT_EQ(farther, 2);
    // A reach short of the far edge keeps only what is within it.
    const ContactPatch short_reach = contactPatch(a, Pose{}, b, pb, cache, r, 1e-3, 0.5 * (gap + far));
    EXPECT_EQ(short_reach.points.size(), 2u);
    for (double g : short_reach.gaps) EXPECT_NEAR(g, gap, 1e-9);
}

// Two boxes overlapping by 2-20 mm (the exact depth by brute-force SAT), their speculative patch
// built from a fresh query: the patch must reach where they overlap, not only a shallow corner the
// normal's faces hold. In a turning drum of boxes, pairs 1.4 cm deep had patches whose every point
// lay 0.3-1 mm apart, so no solve pushed where they overlapped and they sank a millimetre a frame.
// The ruler is the SAT depth (its half, which the query's MPR depth is well within here).
TEST(NarrowphaseContactPatch, SpeculativePatchReachesTheOverlap) {
    std::mt19937_64 rng(20261206);
    std::uniform_real_distribution<double> size(0.04, 0.1), unit(-1.0, 1.0);
    int checked = 0;
    for (int trial = 0; trial < 4000 && checked < 400; ++trial) {
        const Vec3 ha(size(rng), size(rng), size(rng)), hb(size(rng), size(rng), size(rng));
        const Pose pa{Vec3::Zero(), randomRotation(rng)};
        const Vec3 dir = Vec3(unit(rng), unit(rng), unit(rng)).normalized();
        const Pose pb{dir * (ha.norm() + hb.norm()) * (0.45 + 0.3 * std::abs(unit(rng))), randomRotation(rng)};
        const ConvexPolyhedron poly_a = ConvexPolyhedron::box(ha), poly_b = ConvexPolyhedron::box(hb);
        const SatResult sat = bruteForceSat(toWorld(poly_a, pa), toWorld(poly_b, pb));
        if (!(sat.separation < -0.002 && sat.separation > -0.02)) continue;
        const ConvexMesh a = ConvexMesh::box(ha), b = ConvexMesh::box(hb);
        FeatureCache cache;
        const ProximityResult r = queryMeshMesh(a, pa, b, pb, cache);
        const double cd = 1e-3;
        const ContactPatch patch = contactPatch(a, pa, b, pb, cache, r, cd, 0.02);
        ASSERT_FALSE(patch.gaps.empty());
        const double deepest = *std::min_element(patch.gaps.begin(), patch.gaps.end());
        EXPECT_LE(deepest, 0.5 * sat.separation)
            << "trial " << trial << ": SAT depth " << -sat.separation << " m, query " << r.distance
            << " m, the patch's deepest point " << deepest << " m\n"
            << "  ha = " << cppVec(ha) << ", hb = " << cppVec(hb) << "\n  pa = {Vec3::Zero(), " << cppQuat(pa.orientation)
            << "}, pb = {" << cppVec(pb.position) << ", " << cppQuat(pb.orientation) << "}";
        ++checked;
    }
    EXPECT_GE(checked, 400);
}

// Two cubes turned 45 degrees about z, side by side along x, meet edge to edge: the speculative patch
// is the whole shared edge, z from -h to h, with any turn of one of them that rounding leaves (a
// 1e-15 rad turn made it a sliver at one end: an impact there set the cubes spinning).
TEST(NarrowphaseContactPatch, ParallelEdgesGiveTheWholeEdgeWhateverTurnRoundingLeaves) {
    const double h = 0.05, half = h * std::sqrt(2.0), gap = 0.0086;
    const ConvexMesh m = ConvexMesh::box(Vec3(h, h, h));
    const Quat turned(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitZ()));
    const std::array<Vec3, 2> axes{Vec3::UnitX(), Vec3::UnitY()};
    for (double tilt : {0.0, 1e-15, 1e-12, 1e-9})
        for (const Vec3& axis : axes) {
            const Pose pa{Vec3(0.35, 0, 0), Quat(Eigen::AngleAxisd(tilt, axis)) * turned};
            const Pose pb{Vec3(0.35 + 2 * half + gap, 0, 0), turned};
            FeatureCache cache;
            const ProximityResult r = queryMeshMesh(m, pa, m, pb, cache);
            const ContactPatch patch = contactPatch(m, pa, m, pb, cache, r, 1e-3, 0.0135);
            ASSERT_GE(patch.points.size(), 2u) << "tilt " << tilt << " about " << axis.transpose();
            double lo = 1.0, hi = -1.0;
            for (const Vec3& p : patch.points) {
                lo = std::min(lo, p.z());
                hi = std::max(hi, p.z());
                EXPECT_NEAR(p.y(), 0.0, 1e-6) << "tilt " << tilt << " about " << axis.transpose();
            }
            EXPECT_NEAR(lo, -h, 1e-6) << "tilt " << tilt << " about " << axis.transpose();
            EXPECT_NEAR(hi, h, 1e-6) << "tilt " << tilt << " about " << axis.transpose();
        }
}

}  // namespace
}  // namespace vroc::native::testing
