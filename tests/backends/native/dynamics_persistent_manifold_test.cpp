// SPDX-License-Identifier: MIT
// Persistent manifolds: reduction to 4 points against a brute-force best quadrilateral, and the
// warm start carrying impulses to coinciding points (and only to them).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "dynamics/persistent_manifold.h"

namespace vroc::native {
namespace {

double polygonArea(const std::vector<Vec3>& p, const Vec3& n) {
    double a = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) a += p[i].cross(p[(i + 1) % p.size()]).dot(n);
    return 0.5 * std::abs(a);
}

TEST(DynamicsPersistentManifold, ReductionKeepsMostOfTheArea) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0.5, 1.5);
    const Vec3 n = Vec3::UnitZ();
    for (int trial = 0; trial < 100; ++trial) {
        const int k = 5 + static_cast<int>(rng() % 8);   // a convex polygon: points on an ellipse, CCW
        const double ax = u(rng), ay = u(rng);
        std::vector<Vec3> poly;
        for (int i = 0; i < k; ++i) {
            const double t = 2 * M_PI * (i + 0.3 * u(rng)) / k;
            poly.emplace_back(ax * std::cos(t), ay * std::sin(t), 0.0);
        }
        const std::vector<Vec3> kept = reduceContactPoints(poly, n);
        ASSERT_EQ(kept.size(), kMaxManifoldPoints);
        double best = 0.0;   // brute force: the largest quadrilateral from the polygon's vertices
        for (int a = 0; a < k; ++a)
            for (int b = a + 1; b < k; ++b)
                for (int c = b + 1; c < k; ++c)
                    for (int d = c + 1; d < k; ++d)
                        best = std::max(best, polygonArea({poly[a], poly[b], poly[c], poly[d]}, n));
        EXPECT_GE(polygonArea(kept, n), 0.8 * best) << "trial " << trial;
        EXPECT_LE(polygonArea(kept, n), best * (1 + 1e-12));
    }
    const std::vector<Vec3> three{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    EXPECT_EQ(reduceContactPoints(three, n), three);
}

TEST(DynamicsPersistentManifold, WarmStartMatchesCoincidingPointsOnly) {
    Pose frame_a;
    frame_a.position = Vec3(1, 2, 3);
    frame_a.orientation = Quat(Eigen::AngleAxisd(0.7, Vec3(0, 0, 1)));
    ContactManifold solved;
    solved.points = {frame_a.apply(Vec3(0, 0, 0)), frame_a.apply(Vec3(0.1, 0, 0)), frame_a.apply(Vec3(0, 0.1, 0))};
    solved.point_impulse = {1.0, 2.0, 3.0};
    solved.tangent_impulse = Vec3(0.5, 0, 0);
    solved.torsion_impulse = 0.25;
    PersistentManifold cache;
    storeManifold(cache, frame_a, 0.01, solved);
    // The body moved and turned: the same material points, one new point, one lost point.
    Pose moved;
    moved.position = Vec3(1.5, 2, 3);
    moved.orientation = Quat(Eigen::AngleAxisd(0.9, Vec3(0, 0, 1)));
    ContactManifold next;
    next.points = {moved.apply(Vec3(0.1, 0, 0)), moved.apply(Vec3(0.05, 0.05, 0)), moved.apply(Vec3(0, 0, 0))};
    warmStartManifold(cache, moved, 0.005, 1e-3, next);   // half the step: half the impulse
    ASSERT_EQ(next.point_impulse.size(), 3u);
    EXPECT_DOUBLE_EQ(next.point_impulse[0], 1.0);   // 2.0 x 0.5
    EXPECT_DOUBLE_EQ(next.point_impulse[1], 0.0);   // new point: cold
    EXPECT_DOUBLE_EQ(next.point_impulse[2], 0.5);   // 1.0 x 0.5
    EXPECT_DOUBLE_EQ(next.torsion_impulse, 0.125);
    // A longer step scales it up in proportion (a resting load is m g h), at most 3x.
    warmStartManifold(cache, moved, 0.02, 1e-3, next);
    EXPECT_DOUBLE_EQ(next.point_impulse[0], 4.0);
    warmStartManifold(cache, moved, 0.1, 1e-3, next);
    EXPECT_DOUBLE_EQ(next.point_impulse[0], 6.0);
}

}  // namespace
}  // namespace vroc::native
