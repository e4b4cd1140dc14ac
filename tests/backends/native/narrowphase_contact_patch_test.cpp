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

}  // namespace
}  // namespace vroc::native::testing
