// SPDX-License-Identifier: MIT
// Exactly touching boxes (gap 0, the way scenes place bodies on a floor or on one another): the
// query must report touching (distance 0, not penetrating) with the face normal, whatever the
// heading about z. Regression for issue 4's slide8 check: at headings 145 and 325 deg the
// penetration path used to return the horizontal normal (0.707, -0.707, 0).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <fmt/format.h>

#include "geometry/convex_mesh.h"
#include "narrowphase/contact_patch.h"
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

/// A cube set on another half a cube along x, its pose off by what resting solves leave (1e-11 m and
/// 1e-11 rad in every direction), high in a pyramid (row 10 of 1 m cubes): the answer is the
/// top face's normal, touching or apart by that noise. The walk may end on two parallel edges 2e-11
/// m apart, whose direction between closest points is noise: a zero-gap pyramid of 30 rows lost a
/// cube's support that way (its normal 62 deg off the vertical) and the cube fell for a frame.
/// Then the patch: on fixed ticks (a speculative reach), the two faces' overlap rectangle
/// [x0, x0 + 0.5] x [-0.5, 0.5], by its corners, whatever features the walk stopped at.
TEST(NarrowphaseTouching, CubeSetHalfACubeOverAnotherWithTheNoiseOfRestingSolves) {
    const ConvexMesh cube = ConvexMesh::fromPolyhedron(ConvexPolyhedron::box(Vec3(0.5, 0.5, 0.5)));
    std::mt19937_64 rng(2212);
    std::uniform_real_distribution<double> noise(-2e-11, 2e-11);
    auto jitter = [&](const Vec3& at) {
        const Vec3 axis(noise(rng), noise(rng), noise(rng));
        return Pose{at + Vec3(noise(rng), noise(rng), noise(rng)),
                    Quat(Eigen::AngleAxisd(axis.norm(), axis.normalized())).normalized()};
    };
    int bad_normals = 0, bad_patches = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const double x0 = -4.5 + 0.5 * (trial % 19);
        const Pose pa = jitter(Vec3(x0, 0.0, 10.5)), pb = jitter(Vec3(x0 + 0.5, 0.0, 11.5));
        FeatureCache cache;
        const ProximityResult r = queryMeshMesh(cube, pa, cube, pb, cache);
        SCOPED_TRACE(fmt::format("trial {}", trial));
        if (std::abs(r.distance) > 1e-9 || (r.normal - Vec3::UnitZ()).norm() > 1e-6) {
            if (++bad_normals <= 3) ADD_FAILURE() << describe(pa, pb, r);
            continue;
        }
        const ContactPatch patch = contactPatch(cube, pa, cube, pb, cache, r, 1e-4, 1e-3);
        bool corners = patch.points.size() >= 4;
        for (const Vec3& c : {Vec3(x0, -0.5, 11.0), Vec3(x0 + 0.5, -0.5, 11.0), Vec3(x0 + 0.5, 0.5, 11.0), Vec3(x0, 0.5, 11.0)})
            corners = corners && std::any_of(patch.points.begin(), patch.points.end(),
                                             [&](const Vec3& p) { return (p - c).norm() < 1e-6; });
        if (!corners && ++bad_patches <= 3)
            ADD_FAILURE() << describe(pa, pb, r) << fmt::format("patch of {} points, centroid ({}, {}, {})\n",
                                                               patch.points.size(), patch.centroid.x(),
                                                               patch.centroid.y(), patch.centroid.z());
    }
    EXPECT_EQ(bad_normals, 0);
    EXPECT_EQ(bad_patches, 0);
}

/// fcl-style regression, from a zero-gap pyramid of 50 rows of 1 m cubes on fixed ticks (the cube
/// r46_b01 on r45_b01): the first tick's query at the placed poses, the second's from its cached
/// features at the poses the first solve left. The walk then stopped at a side face of the lower
/// cube; the touching normal is the top face's, and the patch built on the side face held one point
/// under each upper cube: it sank 0.74 mm in that tick. The patch is the overlap rectangle.
TEST(NarrowphaseTouching, ZeroGapPyramidCubeKeepsItsOverlapPatchOnTheSecondTick) {
    const ConvexMesh cube = ConvexMesh::fromPolyhedron(ConvexPolyhedron::box(Vec3(0.5, 0.5, 0.5)));
    FeatureCache cache;
    const ProximityResult first = queryMeshMesh(cube, Pose{Vec3(-1.0, 0.0, 45.5), Quat::Identity()}, cube,
                                                Pose{Vec3(-0.5, 0.0, 46.5), Quat::Identity()}, cache);
    ASSERT_EQ(first.distance, 0.0);
    // Quat(w, x, y, z) from the run's [x, y, z, w].
    const Pose pa{Vec3(-0.99999999999995814, 1.7461566689064936e-15, 45.500000000000114),
                  Quat(1.0, -5.0529535846944101e-17, -3.6968868792932924e-14, 4.3235873389201712e-16)};
    const Pose pb{Vec3(-0.49999999999995237, 2.0285217594644472e-15, 46.500000000000128),
                  Quat(1.0, -9.7281936985532167e-17, -2.9621562620795093e-14, 5.8679102154741134e-16)};
    const ProximityResult r = queryMeshMesh(cube, pa, cube, pb, cache);
    ASSERT_LE(std::abs(r.distance), 1e-12) << describe(pa, pb, r);
    ASSERT_LE((r.normal - Vec3::UnitZ()).norm(), 1e-9) << describe(pa, pb, r);
    // Overlap of [-1.5, -0.5] and [-1, 0] in x, [-0.5, 0.5] in y: centroid (-0.75, 0, 46). With a
    // reach (fixed ticks) and without (the event-driven regimes, whose piece of the lower cube was
    // then the side face's top edge: a patch of two points).
    for (double reach : {1e-3, 0.0}) {
        const ContactPatch patch = contactPatch(cube, pa, cube, pb, cache, r, 1e-4, reach);
        ASSERT_EQ(patch.points.size(), 4u) << describe(pa, pb, r) << "reach " << reach;
        EXPECT_LE((patch.centroid - Vec3(-0.75, 0.0, 46.0)).norm(), 1e-9) << "reach " << reach;
    }
}

}  // namespace
}  // namespace vroc::native
