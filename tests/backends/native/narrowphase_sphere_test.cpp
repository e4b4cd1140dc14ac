// SPDX-License-Identifier: MIT
// Exact sphere-sphere and sphere-mesh queries against closed forms and brute force.
#include "narrowphase/point_mesh_walk.h"
#include "narrowphase_check.h"

namespace vroc::native::testing {
namespace {

TEST(NarrowphaseSphere, SphereSphereClosedForm) {
    const ProximityResult r = querySphereSphere(Vec3(0, 0, 0), 0.5, Vec3(3, 4, 0), 1.5);
    EXPECT_DOUBLE_EQ(r.distance, 3.0);   // |c| = 5, minus 2
    EXPECT_NEAR((r.normal - Vec3(0.6, 0.8, 0)).norm(), 0, 1e-15);
    EXPECT_NEAR((r.point_a - Vec3(0.3, 0.4, 0)).norm(), 0, 1e-15);
    EXPECT_NEAR((r.point_b - Vec3(2.1, 2.8, 0)).norm(), 0, 1e-15);
    const ProximityResult p = querySphereSphere(Vec3(0, 0, 0), 1.0, Vec3(0, 0, 1.5), 1.0);
    EXPECT_TRUE(p.penetrating);
    EXPECT_DOUBLE_EQ(p.distance, -0.5);
}

TEST(NarrowphaseSphere, SphereBoxClosedForms) {
    const ConvexMesh box = ConvexMesh::box(Vec3(1, 2, 3));
    FeatureCache cache;
    // Face region, edge region, vertex region, inside.
    ProximityResult r = querySphereMesh(Vec3(0, 0, 5), 1.0, box, Pose{}, cache);
    EXPECT_NEAR(r.distance, 1.0, 1e-15);
    EXPECT_NEAR((r.normal - Vec3(0, 0, -1)).norm(), 0, 1e-15);
    r = querySphereMesh(Vec3(4, 0, 7), 1.0, box, Pose{}, cache);
    EXPECT_NEAR(r.distance, 4.0, 1e-15);   // |(3, 0, 4)| - 1
    r = querySphereMesh(Vec3(2, 3, 4), 0.5, box, Pose{}, cache);
    EXPECT_NEAR(r.distance, std::sqrt(3.0) - 0.5, 1e-15);
    r = querySphereMesh(Vec3(0.8, 0, 0), 0.5, box, Pose{}, cache);
    EXPECT_TRUE(r.penetrating);
    EXPECT_NEAR(r.distance, -0.7, 1e-15);   // 0.2 below the x = 1 face, radius 0.5
    EXPECT_NEAR((r.normal - Vec3(-1, 0, 0)).norm(), 0, 1e-15);   // sphere -> mesh
}

TEST(NarrowphaseSphere, RandomPointsAgainstBruteForce) {
    std::mt19937_64 rng(31);
    for (int k = 0; k < 200; ++k) {
        const ConvexPolyhedron poly = randomHull(rng, 20, 1.0);
        const ConvexMesh mesh = ConvexMesh::fromPolyhedron(poly);
        const Pose pose{Vec3(0.3, -0.2, 0.1), randomRotation(rng)};
        const WorldHull w = toWorld(poly, pose);
        FeatureCache cache;
        for (int i = 0; i < 50; ++i) {
            std::normal_distribution<double> g;
            const Vec3 c = pose.position + Vec3(g(rng), g(rng), g(rng)) * 1.2;
            const ProximityResult r = querySphereMesh(c, 0.25, mesh, pose, cache);
            ASSERT_TRUE(r.converged);
            // Brute force: outside -> min over faces (inside projection) and edges; inside -> max plane distance.
            const double inside = surfaceDistance(w, c);
            double ref = inside;
            if (inside > 0) {
                WorldHull point;
                point.vertices = {c};
                Closest best;
                vertexFaces(point, w, true, best);
                for (const auto& e : w.edges) segmentSegment(c, c, w.vertices[e.first], w.vertices[e.second], best);
                ref = best.distance;
            }
            ASSERT_NEAR(r.distance, ref - 0.25, 1e-12) << "hull " << k << " point " << i;
            ASSERT_NEAR(std::abs(surfaceDistance(w, r.point_b)), 0.0, 1e-12);
        }
    }
}

}  // namespace
}  // namespace vroc::native::testing
