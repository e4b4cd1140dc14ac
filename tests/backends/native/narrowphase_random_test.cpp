// SPDX-License-Identifier: MIT
// 1e5 random hull pairs (plus larger hulls) against brute force, SAT and libccd, cold and warm.
#include <chrono>

#include "narrowphase_check.h"

namespace vroc::native::testing {
namespace {

struct Pool {
    std::vector<ConvexPolyhedron> polys;
    std::vector<ConvexMesh> meshes;
};

Pool makePool(std::mt19937_64& rng, int count, int min_n, int max_n) {
    Pool pool;
    std::uniform_int_distribution<int> n(min_n, max_n);
    for (int i = 0; i < count; ++i) {
        pool.polys.push_back(randomHull(rng, n(rng), 1.0));
        pool.meshes.push_back(ConvexMesh::fromPolyhedron(pool.polys.back()));
    }
    return pool;
}

/// Runs `pairs` random queries; each pair is queried cold, then warm from a random stale cache.
void runRandomPairs(std::uint64_t seed, long pairs, int min_n, int max_n, double scale, double tolerance = 1e-9) {
    std::mt19937_64 rng(seed);
    Pool pool = makePool(rng, 64, min_n, max_n);
    std::uniform_int_distribution<int> pick(0, 63);
    std::uniform_real_distribution<double> sep(0.0, 3.0);
    CheckStats stats;
    long failures = 0;
    FeatureCache stale;
    for (long i = 0; i < pairs && failures < 5; ++i) {
        const int ia = pick(rng), ib = pick(rng);
        Pose pa{Vec3::Zero(), randomRotation(rng)}, pb{Vec3::Zero(), randomRotation(rng)};
        std::normal_distribution<double> g;
        pb.position = Vec3(g(rng), g(rng), g(rng)).normalized() * sep(rng) * scale;
        ConvexPolyhedron a = pool.polys[ia], b = pool.polys[ib];
        for (Vec3& v : a.vertices) v *= scale;
        for (Vec3& v : b.vertices) v *= scale;
        for (double& o : a.face_offsets) o *= scale;
        for (double& o : b.face_offsets) o *= scale;
        const ConvexMesh ma = ConvexMesh::fromPolyhedron(a), mb = ConvexMesh::fromPolyhedron(b);
        // Alternate cold queries and queries from another pair's (stale, possibly invalid) cache.
        FeatureCache cache = (i % 2) ? stale : FeatureCache{};
        const FeatureCache before = cache;
        const ProximityResult r = queryMeshMesh(ma, pa, mb, pb, cache);
        stale = cache;
        CheckOptions opt;
        opt.tolerance = tolerance;
        // libccd's GJK and MPR use absolute epsilons: below ~0.1 m they misjudge overlaps (this
        // suite found GJK calling 0.3 mm-deep overlaps of 1 mm hulls "apart"), so compare above.
        opt.compare_libccd = (i % 10 == 0) && scale >= 0.1;
        const std::string err = checkQuery(a, ma, pa, b, mb, pb, cache, r, opt, &stats);
        if (!err.empty()) {
            ++failures;
            ADD_FAILURE() << "pair " << i << ":\n" << err << "  // before the query:\n" << cacheText(before) << regressionTest(fmt::format("Random{}_{}", seed, i), a, pa, b, pb);
        }
    }
    EXPECT_GT(stats.separated, pairs / 10);
    EXPECT_GT(stats.penetrating, pairs / 10);
}

TEST(NarrowphaseRandom, HundredThousandSmallHullPairs) { runRandomPairs(1, 100000, 4, 12, 1.0); }
TEST(NarrowphaseRandom, LargerHulls) { runRandomPairs(2, 1000, 30, 60, 1.0); }
TEST(NarrowphaseRandom, MillimetreScale) { runRandomPairs(3, 5000, 4, 16, 1e-3); }
TEST(NarrowphaseRandom, KilometreScale) { runRandomPairs(4, 5000, 4, 16, 1e3); }

}  // namespace
}  // namespace vroc::native::testing
