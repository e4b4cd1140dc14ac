// SPDX-License-Identifier: MIT
// Degenerate configurations generated on purpose: parallel faces, edge on edge, vertex on face,
// exactly touching, identical (coincident) hulls, sliver faces, and scales 1 mm .. 1 km.
#include "narrowphase_check.h"

namespace vroc::native::testing {
namespace {

Quat axisAngle(double angle, const Vec3& axis) { return Quat(Eigen::AngleAxisd(angle, axis.normalized())); }

/// Checks one configuration cold and from every feature pair of a few seeds (stale caches).
void check(const ConvexPolyhedron& a, const Pose& pa, const ConvexPolyhedron& b, const Pose& pb, double tol,
           bool compare_points, const std::string& name) {
    const ConvexMesh ma = ConvexMesh::fromPolyhedron(a), mb = ConvexMesh::fromPolyhedron(b);
    CheckOptions opt;
    opt.tolerance = tol;
    opt.compare_points = compare_points;
    opt.compare_libccd = ma.scale() >= 0.1;
    std::vector<FeatureCache> starts{FeatureCache{}};
    for (int v = 0; v < std::min(ma.vertexCount(), 4); ++v)
        for (FeatureType t : {FeatureType::Vertex, FeatureType::Edge, FeatureType::Face})
            starts.push_back({{FeatureType::Vertex, v}, {t, 0}});
    for (const FeatureCache& start : starts) {
        FeatureCache cache = start;
        const ProximityResult r = queryMeshMesh(ma, pa, mb, pb, cache);
        const std::string err = checkQuery(a, ma, pa, b, mb, pb, cache, r, opt);
        if (!err.empty()) {
            ADD_FAILURE() << name << ":\n" << err << "  // before the query:\n" << cacheText(start) << regressionTest(name, a, pa, b, pb);
            return;
        }
    }
}

class NarrowphaseScaled : public ::testing::TestWithParam<double> {};

TEST_P(NarrowphaseScaled, ParallelFacesOfBoxes) {
    const double s = GetParam();
    const auto box = ConvexPolyhedron::box(Vec3(0.5, 0.3, 0.2) * s);
    for (double gap : {0.0, 1e-12, 1e-6, 0.01, 0.5})
        for (double slide : {0.0, 0.2, 0.45, 0.9})
            check(box, Pose{}, box, Pose{Vec3(1.0 * s + gap * s, slide * s, -slide * 0.3 * s), Quat::Identity()},
                  1e-9 * std::max(1.0, s * 1e-3), false, fmt::format("ParallelFaces_s{}_gap{}_slide{}", s, gap, slide));
}

TEST_P(NarrowphaseScaled, EdgeOnEdge) {
    const double s = GetParam();
    const auto box = ConvexPolyhedron::box(Vec3(0.5, 0.5, 0.5) * s);
    // B turned 45 deg about x, then about z: its lowest edge crosses A's top edges or faces.
    for (double gap : {0.0, 1e-9, 1e-3, 0.3})
        for (double zturn : {0.0, 0.3, M_PI / 4}) {
            const Quat q = axisAngle(zturn, Vec3::UnitZ()) * axisAngle(M_PI / 4, Vec3::UnitX());
            const double drop = 0.5 * s + 0.5 * std::sqrt(2.0) * s + gap * s;
            check(box, Pose{}, box, Pose{Vec3(0.5 * s, 0.0, drop), q}, 1e-9 * std::max(1.0, s * 1e-3), false,
                  fmt::format("EdgeOnEdge_s{}_gap{}_z{}", s, gap, zturn));
        }
}

TEST_P(NarrowphaseScaled, VertexOnFace) {
    const double s = GetParam();
    const auto box = ConvexPolyhedron::box(Vec3(0.5, 0.5, 0.5) * s);
    // B's body diagonal vertical: one vertex points straight down onto A's top face.
    const Quat q = Quat::FromTwoVectors(Vec3(-1, -1, -1).normalized(), -Vec3::UnitZ());
    for (double gap : {0.0, 1e-10, 1e-4, 0.2})
        for (double x : {0.0, 0.25, 0.49}) {
            const double drop = 0.5 * s + 0.5 * std::sqrt(3.0) * s + gap * s;
            check(box, Pose{}, box, Pose{Vec3(x * s, 0.1 * x * s, drop), q}, 1e-9 * std::max(1.0, s * 1e-3), true,
                  fmt::format("VertexOnFace_s{}_gap{}_x{}", s, gap, x));
        }
}

TEST_P(NarrowphaseScaled, IdenticalCoincidentAndShiftedHulls) {
    const double s = GetParam();
    std::mt19937_64 rng(7);
    for (int i = 0; i < 10; ++i) {
        ConvexPolyhedron h = randomHull(rng, 12, s);
        const Quat q = randomRotation(rng);
        check(h, Pose{Vec3::Zero(), q}, h, Pose{Vec3::Zero(), q}, 1e-9 * std::max(1.0, s * 1e-3), false, "Coincident");
        check(h, Pose{Vec3::Zero(), q}, h, Pose{Vec3(0.1 * s, 0, 0), q}, 1e-9 * std::max(1.0, s * 1e-3), false, "Shifted");
    }
}

TEST_P(NarrowphaseScaled, SliverHulls) {
    const double s = GetParam();
    std::mt19937_64 rng(11);
    for (int i = 0; i < 200; ++i) {
        const ConvexPolyhedron a = randomHull(rng, 10, s, 1e-3);   // flat: sliver faces on the rim
        const ConvexPolyhedron b = randomHull(rng, 8, s, i % 2 ? 1e-3 : 1.0);
        std::normal_distribution<double> g;
        const Pose pb{Vec3(g(rng), g(rng), g(rng)).normalized() * (0.05 + 2.0 * (i % 10) / 10.0) * s, randomRotation(rng)};
        check(a, Pose{Vec3::Zero(), randomRotation(rng)}, b, pb, 1e-9 * std::max(1.0, s * 1e-3), false, fmt::format("Sliver_s{}_{}", s, i));
    }
}

INSTANTIATE_TEST_SUITE_P(Scales, NarrowphaseScaled, ::testing::Values(1e-3, 1.0, 1e3));

TEST(NarrowphaseDegenerate, ExactlyTouchingBoxesReportZeroDistance) {
    const auto box = ConvexPolyhedron::box(Vec3(0.5, 0.5, 0.5));
    const ConvexMesh m = ConvexMesh::fromPolyhedron(box);
    FeatureCache cache;
    const ProximityResult r = queryMeshMesh(m, Pose{}, m, Pose{Vec3(1.0, 0.25, 0.0), Quat::Identity()}, cache);
    EXPECT_EQ(r.distance, 0.0);   // closed form: faces x = 0.5 coincide
    EXPECT_TRUE(r.converged);
    EXPECT_NEAR(r.normal.x(), 1.0, 1e-12);
}

}  // namespace
}  // namespace vroc::native::testing
