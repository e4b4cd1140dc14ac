// SPDX-License-Identifier: MIT
// Coherent sequences: small motions between queries, the cache carried along. Asserts zero
// step-bound hits (no cycles), a small mean and max walk-step count, and agreement with the
// brute-force reference at every query.
#include "narrowphase_check.h"

namespace vroc::native::testing {
namespace {

void coherentSequence(std::uint64_t seed, int n, double centre_distance, double mean_steps_limit) {
    std::mt19937_64 rng(seed);
    const ConvexPolyhedron a = randomHull(rng, n, 1.0), b = randomHull(rng, n, 1.0);
    const ConvexMesh ma = ConvexMesh::fromPolyhedron(a), mb = ConvexMesh::fromPolyhedron(b);
    const Quat step_a(Eigen::AngleAxisd(0.1 * M_PI / 180, Vec3(1, 2, 3).normalized()));
    const Quat step_b(Eigen::AngleAxisd(0.1 * M_PI / 180, Vec3(-2, 1, 0.5).normalized()));
    Pose pa{Vec3::Zero(), randomRotation(rng)}, pb{Vec3(centre_distance, 0.1, -0.05), randomRotation(rng)};
    FeatureCache cache;
    long steps = 0, max_steps = 0;
    const int queries = 2000;
    CheckOptions opt;
    opt.compare_libccd = false;
    opt.compare_points = false;   // closest points are checked on the surfaces and against the distance
    for (int i = 0; i < queries; ++i) {
        pa.orientation = (step_a * pa.orientation).normalized();
        pb.orientation = (step_b * pb.orientation).normalized();
        const ProximityResult r = queryMeshMesh(ma, pa, mb, pb, cache);
        ASSERT_TRUE(r.converged) << "query " << i << regressionTest("Coherent", a, pa, b, pb);
        if (i > 0) {   // the first query is a cold start
            steps += r.walk_steps;
            max_steps = std::max<long>(max_steps, r.walk_steps);
        }
        if (i % (n > 64 ? 250 : 20) == 0) {
            const std::string err = checkQuery(a, ma, pa, b, mb, pb, cache, r, opt);
            ASSERT_EQ(err, "") << "query " << i << regressionTest("Coherent", a, pa, b, pb);
        }
    }
    const double mean = static_cast<double>(steps) / (queries - 1);
    EXPECT_LE(mean, mean_steps_limit);
    EXPECT_LE(max_steps, 12);
    ::testing::Test::RecordProperty("mean_walk_steps", std::to_string(mean));
}

TEST(NarrowphaseCoherent, SeparatedSmallHulls) { coherentSequence(21, 8, 2.5, 1.5); }
TEST(NarrowphaseCoherent, SeparatedLargeHulls) { coherentSequence(22, 128, 2.3, 1.5); }
TEST(NarrowphaseCoherent, OverlappingHulls) { coherentSequence(23, 32, 1.2, 1.5); }
TEST(NarrowphaseCoherent, BoxesRestingFaceOnFace) {
    // A box sliding and turning slowly on another: parallel faces the whole time.
    const ConvexPolyhedron box = ConvexPolyhedron::box(Vec3(0.5, 0.5, 0.5));
    const ConvexMesh m = ConvexMesh::fromPolyhedron(box);
    FeatureCache cache;
    long steps = 0;
    for (int i = 0; i < 2000; ++i) {
        const Pose pb{Vec3(0.3 * std::sin(i * 1e-3), 0.2 * std::cos(i * 1e-3), 1.0 + 1e-4),
                      Quat(Eigen::AngleAxisd(i * 1e-3, Vec3::UnitZ()))};
        const ProximityResult r = queryMeshMesh(m, Pose{}, m, pb, cache);
        ASSERT_TRUE(r.converged);
        ASSERT_NEAR(r.distance, 1e-4, 1e-12) << "query " << i;   // closed form: the face gap
        if (i > 0) steps += r.walk_steps;
    }
    EXPECT_LE(steps / 1999.0, 1.5);
}

}  // namespace
}  // namespace vroc::native::testing
