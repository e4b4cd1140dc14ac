// SPDX-License-Identifier: MIT
// The long suite (CTest label "long", `make test-long`): 1e7 random hull pairs against the
// brute-force reference, SAT and (every 100th) libccd, mixing scales, slivers and stale caches.
#include "narrowphase_check.h"

namespace vroc::native::testing {
namespace {

TEST(NarrowphaseLong, TenMillionRandomPairs) {
    std::mt19937_64 rng(12345);
    std::vector<ConvexPolyhedron> polys;
    std::vector<ConvexMesh> meshes;
    for (int i = 0; i < 128; ++i) {
        polys.push_back(randomHull(rng, 4 + i % 13, 1.0, i % 8 == 7 ? 1e-3 : 1.0));
        meshes.push_back(ConvexMesh::fromPolyhedron(polys.back()));
    }
    std::uniform_int_distribution<int> pick(0, 127);
    std::uniform_real_distribution<double> sep(0.0, 3.0);
    std::normal_distribution<double> g;
    FeatureCache stale;
    long failures = 0;
    for (long i = 0; i < 10'000'000 && failures < 5; ++i) {
        const int ia = pick(rng), ib = pick(rng);
        const Pose pa{Vec3::Zero(), randomRotation(rng)};
        const Pose pb{Vec3(g(rng), g(rng), g(rng)).normalized() * sep(rng), randomRotation(rng)};
        FeatureCache cache = (i % 2) ? stale : FeatureCache{};
        const FeatureCache before = cache;
        const ProximityResult r = queryMeshMesh(meshes[ia], pa, meshes[ib], pb, cache);
        stale = cache;
        CheckOptions opt;
        opt.compare_libccd = (i % 100 == 0);
        const std::string err = checkQuery(polys[ia], meshes[ia], pa, polys[ib], meshes[ib], pb, cache, r, opt);
        if (!err.empty()) {
            ++failures;
            ADD_FAILURE() << "pair " << i << ":\n" << err << "  // before the query:\n" << cacheText(before)
                          << regressionTest(fmt::format("Long{}", i), polys[ia], pa, polys[ib], pb);
        }
    }
}

}  // namespace
}  // namespace vroc::native::testing
