// SPDX-License-Identifier: MIT
// The neutral distance query against analytic answers. A failing case prints its configuration.
#include <gtest/gtest.h>

#include <cmath>

#include "vroc/harness/commands/detail_levels.h"
#include "vroc/harness/metrics/neutral_distance.h"

namespace vroc::harness {
namespace {

Pose at(const Vec3& p, const Quat& q = Quat::Identity()) { return Pose{p, q}; }
const Shape kUnitBox = Shape::box(Vec3(0.5, 0.5, 0.5));

TEST(HarnessDistance, SphereSphere) {
    EXPECT_NEAR(signedDistance(Shape::sphere(1), at(Vec3::Zero()), Shape::sphere(0.5), at(Vec3(3, 0, 0))), 1.5, 1e-15);
    EXPECT_NEAR(signedDistance(Shape::sphere(1), at(Vec3::Zero()), Shape::sphere(0.5), at(Vec3(1.2, 0, 0))), -0.3, 1e-15);
}

TEST(HarnessDistance, SphereBoxFaceEdgeCornerInside) {
    const Shape s = Shape::sphere(0.1);
    EXPECT_NEAR(signedDistance(s, at(Vec3(0, 0, 1)), kUnitBox, at(Vec3::Zero())), 0.4, 1e-15);                  // face
    EXPECT_NEAR(signedDistance(s, at(Vec3(1, 1, 0)), kUnitBox, at(Vec3::Zero())), std::sqrt(0.5) - 0.1, 1e-15); // edge
    EXPECT_NEAR(signedDistance(s, at(Vec3(1, 1, 1)), kUnitBox, at(Vec3::Zero())), std::sqrt(0.75) - 0.1, 1e-15);// corner
    EXPECT_NEAR(signedDistance(s, at(Vec3(0, 0, 0.45)), kUnitBox, at(Vec3::Zero())), -0.15, 1e-15);           // inside
}

TEST(HarnessDistance, BoxBoxFaceToFaceAndOverlap) {
    EXPECT_NEAR(signedDistance(kUnitBox, at(Vec3::Zero()), kUnitBox, at(Vec3(0.2, 0.1, 1.3))), 0.3, 1e-12);
    EXPECT_NEAR(signedDistance(kUnitBox, at(Vec3::Zero()), kUnitBox, at(Vec3(0.2, 0.1, 0.95))), -0.05, 1e-12);
}

TEST(HarnessDistance, BoxBoxEdgeToEdge) {
    // Box B rotated 45° about x and about z... simpler: both boxes rotated 45° about perpendicular
    // axes so their edges cross: A's top edge along y at z = sqrt(0.5), B's bottom edge along x.
    const Quat ra(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitY()));   // top edge of A: along y, z = sqrt(.5)
    const Quat rb(Eigen::AngleAxisd(M_PI / 4, Vec3::UnitX()));   // bottom edge of B: along x
    const double h = std::sqrt(0.5);
    const Pose pb = at(Vec3(0, 0, 2 * h + 0.25), rb);
    EXPECT_NEAR(signedDistance(kUnitBox, at(Vec3::Zero(), ra), kUnitBox, pb), 0.25, 1e-12)
        << "A: unit box rotated 45 deg about y at origin; B: unit box rotated 45 deg about x at z = " << 2 * h + 0.25;
    // Overlapping by 0.1 along z: the SAT depth is the edge-edge overlap 0.1.
    EXPECT_NEAR(signedDistance(kUnitBox, at(Vec3::Zero(), ra), kUnitBox, at(Vec3(0, 0, 2 * h - 0.1), rb)), -0.1, 1e-12);
}

TEST(HarnessDistance, HullAgreesWithTheSameBoxAsBox) {
    std::vector<Vec3> pts;
    for (int i = 0; i < 8; ++i) pts.emplace_back((i & 1) ? 0.5 : -0.5, (i & 2) ? 0.5 : -0.5, (i & 4) ? 0.5 : -0.5);
    const Shape hull = Shape::convexHull(ConvexPolyhedron::fromPoints(pts));
    const Quat q(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
    for (const Vec3& p : {Vec3(1.2, 0.3, 0.9), Vec3(0.2, 0.1, 0.3), Vec3(-2, 0.5, 0)}) {
        EXPECT_NEAR(signedDistance(hull, at(Vec3::Zero()), kUnitBox, at(p, q)), signedDistance(kUnitBox, at(Vec3::Zero()), kUnitBox, at(p, q)), 1e-12)
            << "unit box vs unit box at " << p.transpose() << " rotated 0.7 rad about (1,2,3)";
        EXPECT_NEAR(pointSignedDistance(p, hull, at(Vec3::Zero())), pointSignedDistance(p, kUnitBox, at(Vec3::Zero())), 1e-12);
    }
}

TEST(HarnessDistance, CompoundIsTheMinimumOverParts) {
    const Shape c = Shape::compound({ShapePart{Shape::sphere(0.1), at(Vec3(1, 0, 0))}, ShapePart{kUnitBox, at(Vec3(-1, 0, 0))}});
    EXPECT_NEAR(signedDistance(c, at(Vec3::Zero()), Shape::sphere(0.1), at(Vec3(1, 0, 0.5))), 0.3, 1e-15);
    EXPECT_NEAR(signedDistance(c, at(Vec3::Zero()), Shape::sphere(0.1), at(Vec3(-1, 0, 0.7))), 0.1, 1e-15);
}

TEST(HarnessDetail, DecimationKeepsTheRequestedCountAndExtremes) {
    std::vector<Vec3> v;
    for (int i = 0; i < 40; ++i) v.emplace_back(std::cos(i * 0.157), std::sin(i * 0.157), (i % 2) ? 0.2 : -0.2);
    const auto kept = decimateVertices(v, 0.25);
    EXPECT_EQ(kept.size(), 10u);
    EXPECT_EQ(decimateVertices(v, 0.01).size(), 4u);
    // Farthest-point sampling: the second point is the farthest from the first.
    double far = 0;
    for (const Vec3& p : v) far = std::max(far, (p - v[0]).norm());
    EXPECT_NEAR((kept[1] - v[0]).norm(), far, 1e-15);
}

}  // namespace
}  // namespace vroc::harness
