// SPDX-License-Identifier: MIT
// Exactly touching boxes (gap 0, the way scenes place bodies on a floor or on one another): the
// query must report touching (distance 0, not penetrating) with the face normal, whatever the
// heading about z. Regression for issue 4's slide8 check: at headings 145 and 325 deg the
// penetration path used to return the horizontal normal (0.707, -0.707, 0).
#include <gtest/gtest.h>

#include <cmath>

#include <fmt/format.h>

#include "geometry/convex_mesh.h"
#include "narrowphase/proximity.h"

namespace vroc::native {
namespace {

Quat yaw(double deg) { return Quat(Eigen::AngleAxisd(deg * M_PI / 180.0, Vec3::UnitZ())); }

std::string describe(const Pose& pa, const Pose& pb, const ProximityResult& r) {
    return fmt::format("A at ({:.17g}, {:.17g}, {:.17g}) q [{:.17g}, {:.17g}, {:.17g}, {:.17g}]\n"
                       "B at ({:.17g}, {:.17g}, {:.17g}) q [{:.17g}, {:.17g}, {:.17g}, {:.17g}]\n"
                       "got distance {:.17g} normal ({:.17g}, {:.17g}, {:.17g}) penetrating {}\n",
                       pa.position.x(), pa.position.y(), pa.position.z(), pa.orientation.x(),
                       pa.orientation.y(), pa.orientation.z(), pa.orientation.w(), pb.position.x(),
                       pb.position.y(), pb.position.z(), pb.orientation.x(), pb.orientation.y(),
                       pb.orientation.z(), pb.orientation.w(), r.distance, r.normal.x(), r.normal.y(),
                       r.normal.z(), r.penetrating);
}

/// Queries A-B and B-A (cold cache and a warm one) and checks the touching answer.
void expectTouching(const ConvexMesh& a, const Pose& pa, const ConvexMesh& b, const Pose& pb,
                    const Vec3& normal_ab) {
    for (int order = 0; order < 2; ++order) {
        const bool swap = order == 1;
        const ConvexMesh& ma = swap ? b : a;
        const ConvexMesh& mb = swap ? a : b;
        const Pose& qa = swap ? pb : pa;
        const Pose& qb = swap ? pa : pb;
        const Vec3 expected = swap ? Vec3(-normal_ab) : normal_ab;
        FeatureCache cache;
        for (int repeat = 0; repeat < 2; ++repeat) {   // cold, then from the cached features
            const ProximityResult r = queryMeshMesh(ma, qa, mb, qb, cache);
            EXPECT_LE(std::abs(r.distance), 1e-12) << describe(qa, qb, r);
            EXPECT_FALSE(r.penetrating) << describe(qa, qb, r);
            EXPECT_LE((r.normal - expected).norm(), 1e-9) << describe(qa, qb, r);
        }
    }
}

TEST(NarrowphaseTouching, BoxExactlyOnFloorAtEveryHeading) {
    const ConvexMesh floor = ConvexMesh::fromPolyhedron(ConvexPolyhedron::box(Vec3(10.0, 10.0, 0.5)));
    const ConvexMesh box = ConvexMesh::fromPolyhedron(ConvexPolyhedron::box(Vec3(0.2, 0.15, 0.1)));
    const Pose floor_pose{Vec3(0.0, 0.0, -0.5), Quat::Identity()};
    for (int k = 0; k < 8; ++k) {
        const double heading = 10.0 + 45.0 * k;
        const double c = std::cos(heading * M_PI / 180.0), s = std::sin(heading * M_PI / 180.0);
        const Pose box_pose{Vec3(4.0 * c, 4.0 * s, 0.1), yaw(heading)};
        SCOPED_TRACE(fmt::format("heading {} deg", heading));
        expectTouching(floor, floor_pose, box, box_pose, Vec3::UnitZ());
    }
}

TEST(NarrowphaseTouching, Slide8Slider3ExactConfiguration) {
    // scenes/checks/slide8.json, slider3 (yaw 145 deg), as measured in docs/native-results.md.
    const ConvexMesh floor = ConvexMesh::fromPolyhedron(ConvexPolyhedron::box(Vec3(10.0, 10.0, 0.5)));
    const ConvexMesh box = ConvexMesh::fromPolyhedron(ConvexPolyhedron::box(Vec3(0.2, 0.15, 0.1)));
    const Pose floor_pose{Vec3(0.0, 0.0, -0.5), Quat::Identity()};
    const Quat q(0.300705799504, 0.0, 0.0, 0.953716950748);   // (w, x, y, z) = file [0, 0, 0.9537, 0.3007]
    expectTouching(floor, floor_pose, box, Pose{Vec3(2.828427125, -2.828427125, 0.1), q.normalized()}, Vec3::UnitZ());
    expectTouching(floor, floor_pose, box, Pose{Vec3(-2.828427125, 2.828427125, 0.1), yaw(325.0)}, Vec3::UnitZ());
}

TEST(NarrowphaseTouching, StackedCubesTurnedAboutZ) {
    const ConvexMesh cube = ConvexMesh::fromPolyhedron(ConvexPolyhedron::box(Vec3(0.25, 0.25, 0.25)));
    for (double lower : {0.0, 17.0, 45.0})
        for (double upper : {0.0, 10.0, 45.0, 145.0, 325.0, 359.0}) {
            SCOPED_TRACE(fmt::format("lower {} deg, upper {} deg", lower, upper));
            const Pose pa{Vec3(0.3, -0.2, 0.25), yaw(lower)};
            const Pose pb{Vec3(0.3, -0.2, 0.75), yaw(upper)};
            expectTouching(cube, pa, cube, pb, Vec3::UnitZ());
        }
}

TEST(NarrowphaseTouching, RealOverlapIsStillPenetrationAndSmallGapIsSeparation) {
    const ConvexMesh floor = ConvexMesh::fromPolyhedron(ConvexPolyhedron::box(Vec3(10.0, 10.0, 0.5)));
    const ConvexMesh box = ConvexMesh::fromPolyhedron(ConvexPolyhedron::box(Vec3(0.2, 0.15, 0.1)));
    const Pose floor_pose{Vec3(0.0, 0.0, -0.5), Quat::Identity()};
    for (double heading : {10.0, 145.0, 325.0}) {
        FeatureCache cache;
        const Pose deep{Vec3(1.0, 0.5, 0.1 - 1e-4), yaw(heading)};
        const ProximityResult r = queryMeshMesh(floor, floor_pose, box, deep, cache);
        EXPECT_TRUE(r.penetrating) << describe(floor_pose, deep, r);
        EXPECT_NEAR(r.distance, -1e-4, 1e-9) << describe(floor_pose, deep, r);
        EXPECT_LE((r.normal - Vec3::UnitZ()).norm(), 1e-6) << describe(floor_pose, deep, r);
        FeatureCache cache2;
        const Pose above{Vec3(1.0, 0.5, 0.1 + 1e-9), yaw(heading)};
        const ProximityResult s = queryMeshMesh(floor, floor_pose, box, above, cache2);
        EXPECT_FALSE(s.penetrating) << describe(floor_pose, above, s);
        EXPECT_NEAR(s.distance, 1e-9, 1e-12) << describe(floor_pose, above, s);
        EXPECT_LE((s.normal - Vec3::UnitZ()).norm(), 1e-6) << describe(floor_pose, above, s);
    }
}

}  // namespace
}  // namespace vroc::native
