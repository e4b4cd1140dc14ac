// SPDX-License-Identifier: MIT
// vroc-bench: the coherent pair query of issue 4 ("Speed targets"). Two random hulls of N points
// on the unit sphere turn about 0.1 degree per query, separated or overlapping; the same pose
// sequence is fed to the native V-Clip walk (with its feature cache), Bullet's btGjkPairDetector
// (double precision, btVoronoiSimplexSolver, btConvexHullShape with margin 0, EPA when
// overlapping) and libccd (ccdGJKIntersect when separated -- libccd 2.1 has no distance query --
// and ccdMPRPenetration when overlapping). Counter walk_steps: mean native walk steps per query.
// Run: vroc-bench --benchmark_min_time=0.05 [--benchmark_format=csv]   (scripts/bench.sh)
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <ccd/ccd.h>

#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkEpaPenetrationDepthSolver.h>
#include <BulletCollision/NarrowPhaseCollision/btGjkPairDetector.h>
#include <BulletCollision/NarrowPhaseCollision/btPointCollector.h>
#include <BulletCollision/NarrowPhaseCollision/btVoronoiSimplexSolver.h>

#include "geometry/convex_mesh.h"
#include "narrowphase/proximity.h"

namespace {

using vroc::Mat3;
using vroc::Pose;
using vroc::Quat;
using vroc::Vec3;

constexpr int kPoses = 3600;   // 0.1 degree steps: one full turn, then the sequence repeats

struct Scenario {
    vroc::ConvexPolyhedron a, b;
    std::vector<Pose> poses_a, poses_b;
};

std::vector<Vec3> spherePoints(std::mt19937_64& rng, int n) {
    std::normal_distribution<double> g;
    std::vector<Vec3> pts;
    for (int i = 0; i < n; ++i) pts.push_back(Vec3(g(rng), g(rng), g(rng)).normalized());
    return pts;
}

Scenario makeScenario(int n, bool overlapping) {
    std::mt19937_64 rng(1000 + n);
    Scenario s;
    s.a = vroc::ConvexPolyhedron::fromPoints(spherePoints(rng, n));
    s.b = vroc::ConvexPolyhedron::fromPoints(spherePoints(rng, n));
    const double step = 0.1 * M_PI / 180.0;
    const Vec3 axis_a = Vec3(1, 2, 3).normalized(), axis_b = Vec3(-2, 1, 0.5).normalized();
    const Vec3 offset(overlapping ? 1.3 : 2.6, 0.1, -0.05);
    for (int i = 0; i < kPoses; ++i) {
        s.poses_a.push_back({Vec3::Zero(), Quat(Eigen::AngleAxisd(i * step, axis_a))});
        s.poses_b.push_back({offset, Quat(Eigen::AngleAxisd(i * step, axis_b))});
    }
    return s;
}

void nativeQuery(benchmark::State& state, int n, bool overlapping) {
    const Scenario s = makeScenario(n, overlapping);
    const auto a = vroc::native::ConvexMesh::fromPolyhedron(s.a);
    const auto b = vroc::native::ConvexMesh::fromPolyhedron(s.b);
    vroc::native::FeatureCache cache;
    (void)vroc::native::queryMeshMesh(a, s.poses_a[0], b, s.poses_b[0], cache);   // warm the cache
    long steps = 0, queries = 0, not_converged = 0;
    int i = 0;
    for (auto _ : state) {
        const auto r = vroc::native::queryMeshMesh(a, s.poses_a[i], b, s.poses_b[i], cache);
        benchmark::DoNotOptimize(r.distance);
        steps += r.walk_steps;
        not_converged += r.converged ? 0 : 1;
        ++queries;
        if (++i == kPoses) i = 0;
    }
    state.counters["walk_steps"] = static_cast<double>(steps) / static_cast<double>(queries);
    state.counters["not_converged"] = static_cast<double>(not_converged);
}

btTransform toBullet(const Pose& p) {
    return btTransform(btQuaternion(p.orientation.x(), p.orientation.y(), p.orientation.z(), p.orientation.w()),
                       btVector3(p.position.x(), p.position.y(), p.position.z()));
}

void bulletQuery(benchmark::State& state, int n, bool overlapping) {
    const Scenario s = makeScenario(n, overlapping);
    btConvexHullShape shape_a, shape_b;
    for (const Vec3& v : s.a.vertices) shape_a.addPoint(btVector3(v.x(), v.y(), v.z()), false);
    for (const Vec3& v : s.b.vertices) shape_b.addPoint(btVector3(v.x(), v.y(), v.z()), false);
    shape_a.recalcLocalAabb();
    shape_b.recalcLocalAabb();
    shape_a.setMargin(0);
    shape_b.setMargin(0);
    std::vector<btTransform> ta, tb;
    for (int i = 0; i < kPoses; ++i) {
        ta.push_back(toBullet(s.poses_a[i]));
        tb.push_back(toBullet(s.poses_b[i]));
    }
    btVoronoiSimplexSolver simplex;
    btGjkEpaPenetrationDepthSolver epa;
    int i = 0;
    for (auto _ : state) {
        btGjkPairDetector detector(&shape_a, &shape_b, &simplex, &epa);
        btDiscreteCollisionDetectorInterface::ClosestPointInput input;
        input.m_transformA = ta[i];
        input.m_transformB = tb[i];
        btPointCollector out;
        detector.getClosestPoints(input, out, nullptr);
        benchmark::DoNotOptimize(out.m_distance);
        if (++i == kPoses) i = 0;
    }
}

struct CcdHull {
    const std::vector<Vec3>* local;
    Mat3 rotation;
    Vec3 position;
};

void ccdSupport(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* out) {
    const auto* h = static_cast<const CcdHull*>(obj);
    const Vec3 d = h->rotation.transpose() * Vec3(dir->v[0], dir->v[1], dir->v[2]);
    const std::vector<Vec3>& v = *h->local;
    size_t best = 0;
    double best_dot = d.dot(v[0]);
    for (size_t k = 1; k < v.size(); ++k)
        if (const double x = d.dot(v[k]); x > best_dot) { best_dot = x; best = k; }
    const Vec3 p = h->rotation * v[best] + h->position;
    ccdVec3Set(out, p.x(), p.y(), p.z());
}

void ccdCenter(const void* obj, ccd_vec3_t* out) {
    const auto* h = static_cast<const CcdHull*>(obj);
    ccdVec3Set(out, h->position.x(), h->position.y(), h->position.z());   // unit-sphere hulls: centred
}

void ccdQuery(benchmark::State& state, int n, bool overlapping) {
    const Scenario s = makeScenario(n, overlapping);
    ccd_t ccd;
    CCD_INIT(&ccd);
    ccd.support1 = ccd.support2 = ccdSupport;
    ccd.center1 = ccd.center2 = ccdCenter;
    ccd.max_iterations = 500;
    std::vector<CcdHull> ha, hb;
    for (int i = 0; i < kPoses; ++i) {
        ha.push_back({&s.a.vertices, s.poses_a[i].orientation.toRotationMatrix(), s.poses_a[i].position});
        hb.push_back({&s.b.vertices, s.poses_b[i].orientation.toRotationMatrix(), s.poses_b[i].position});
    }
    int i = 0;
    for (auto _ : state) {
        if (overlapping) {
            ccd_real_t depth;
            ccd_vec3_t dir, pos;
            benchmark::DoNotOptimize(ccdMPRPenetration(&ha[i], &hb[i], &ccd, &depth, &dir, &pos));
            benchmark::DoNotOptimize(depth);
        } else {
            benchmark::DoNotOptimize(ccdGJKIntersect(&ha[i], &hb[i], &ccd));
        }
        if (++i == kPoses) i = 0;
    }
}

}  // namespace

int main(int argc, char** argv) {
    for (bool overlapping : {false, true})
        for (int n : {8, 32, 128, 512, 2048}) {
            const std::string suffix = std::string(overlapping ? "overlapping" : "separated") + "/" + std::to_string(n);
            benchmark::RegisterBenchmark(("coherent/native_vclip/" + suffix).c_str(), nativeQuery, n, overlapping);
            benchmark::RegisterBenchmark(("coherent/bullet_gjk/" + suffix).c_str(), bulletQuery, n, overlapping);
            benchmark::RegisterBenchmark(
                ("coherent/libccd_" + std::string(overlapping ? "mpr_penetration/" : "gjk_intersect/") + suffix).c_str(),
                ccdQuery, n, overlapping);
        }
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
