// SPDX-License-Identifier: MIT
// contactPatch against closed forms: face-face overlap rectangle, edge on face, vertex contact.
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

}  // namespace
}  // namespace vroc::native::testing
