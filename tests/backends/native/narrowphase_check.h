// SPDX-License-Identifier: MIT
// One checked mesh-mesh query: the library's answer against the test-only references
// (brute-force feature pairs, brute-force SAT, libccd). Returns "" or a description of what
// failed followed by a ready-to-paste regression test.
#pragma once

#include <gtest/gtest.h>

#include "geometry/convex_mesh.h"
#include "narrowphase/proximity.h"
#include "narrowphase/sat_penetration.h"
#include "narrowphase_reference.h"

namespace vroc::native::testing {

struct CheckOptions {
    double tolerance = 1e-9;        ///< [m] distance and closest points
    bool compare_points = true;     ///< closest points equal to the reference's (unique closest pair)
    bool compare_libccd = true;     ///< GJK verdict and MPR depth against libccd
};

struct CheckStats {
    long separated = 0, penetrating = 0, touching = 0;
};

inline std::string cacheText(const FeatureCache& c) {
    auto one = [](Feature f) { return fmt::format("Feature{{FeatureType({}), {}}}", static_cast<int>(f.type), f.index); };
    return "  // cache after the query: FeatureCache{" + one(c.a) + ", " + one(c.b) + "}\n";
}

inline std::string checkQuery(const ConvexPolyhedron& pa_poly, const ConvexMesh& ma, const Pose& pose_a,
                              const ConvexPolyhedron& pb_poly, const ConvexMesh& mb, const Pose& pose_b,
                              FeatureCache& cache, const ProximityResult& r, const CheckOptions& opt,
                              CheckStats* stats = nullptr) {
    const double tol = opt.tolerance;
    const double scale = std::max(ma.scale(), mb.scale());
    const WorldHull wa = toWorld(pa_poly, pose_a), wb = toWorld(pb_poly, pose_b);
    const SatResult sat = bruteForceSat(wa, wb);
    std::string err;
    auto fail = [&](const std::string& what) { err += what + "\n"; };
    if (!r.converged) fail("walk did not converge");
    if (!std::isfinite(r.distance) || !r.normal.allFinite() || std::abs(r.normal.norm() - 1) > 1e-9) fail("non-finite result or non-unit normal");
    if (sat.separation > tol) {
        if (stats) ++stats->separated;
        const Closest ref = bruteForceDistance(wa, wb);
        if (r.penetrating) fail(fmt::format("reported penetrating, SAT separation {:.17g}", sat.separation));
        if (std::abs(r.distance - ref.distance) > tol) fail(fmt::format("distance {:.17g} vs brute force {:.17g} (diff {:.3g})", r.distance, ref.distance, r.distance - ref.distance));
        if (std::abs(surfaceDistance(wa, r.point_a)) > tol) fail(fmt::format("point_a off A's surface by {:.3g}", surfaceDistance(wa, r.point_a)));
        if (std::abs(surfaceDistance(wb, r.point_b)) > tol) fail(fmt::format("point_b off B's surface by {:.3g}", surfaceDistance(wb, r.point_b)));
        if (std::abs((r.point_b - r.point_a).norm() - r.distance) > tol) fail("|point_b - point_a| != distance");
        if (opt.compare_points && ((r.point_a - ref.pa).norm() > tol || (r.point_b - ref.pb).norm() > tol))
            fail(fmt::format("closest points differ from brute force by {:.3g} / {:.3g}", (r.point_a - ref.pa).norm(), (r.point_b - ref.pb).norm()));
    } else if (sat.separation < -tol) {
        if (stats) ++stats->penetrating;
        if (!r.penetrating || r.distance > 0) fail(fmt::format("missed penetration: distance {:.17g}, SAT separation {:.17g}", r.distance, sat.separation));
        const double depth = -r.distance;
        // Up to kSatMaxEdgePairs the depth is the exact minimum translation (the library's SAT with
        // Gauss-map pruning, against brute-force SAT over every face normal and edge pair); beyond,
        // MPR's along its portal normal, never below it. Moving B by the depth along the normal
        // must leave the two touching (SAT separation ~ 0).
        if (satAffordable(ma, mb) ? std::abs(depth + sat.separation) > tol : depth < -sat.separation - 1e-9 * scale)
            fail(fmt::format("depth {:.17g}, the exact SAT depth {:.17g} (diff {:.3g})", depth, -sat.separation, depth + sat.separation));
        Pose moved = pose_b;
        moved.position += depth * r.normal;
        const double after = bruteForceSat(wa, toWorld(pb_poly, moved)).separation;
        if (std::abs(after) > 1e-7 * scale) fail(fmt::format("after moving B by depth*normal the SAT separation is {:.3g} (want 0)", after));
        if (opt.compare_libccd) {
            ccd_t ccd = ccdSetup(1e-13 * scale);
            ccd_real_t depth_ccd;
            ccd_vec3_t dir, pos;
            // MPR's portal path depends on rounding near support ties, so libccd's own depth is not
            // compared for equality: both must be valid MPR answers (>= the exact SAT depth).
            if (ccdMPRPenetration(&wa, &wb, &ccd, &depth_ccd, &dir, &pos) != 0) fail("libccd MPR says apart");
            else if (depth_ccd < -sat.separation - 1e-9 * scale) fail(fmt::format("libccd MPR depth {:.17g} below SAT {:.17g}", depth_ccd, -sat.separation));
        }
    } else {
        if (stats) ++stats->touching;
        if (std::abs(r.distance) > 2 * tol) fail(fmt::format("touching pair (SAT {:.3g}) reported at distance {:.17g}", sat.separation, r.distance));
    }
    if (opt.compare_libccd && std::abs(sat.separation) > 1e-6 * scale) {
        ccd_t ccd = ccdSetup(1e-13 * scale);
        const bool gjk = ccdGJKIntersect(&wa, &wb, &ccd) != 0;
        if (gjk != (sat.separation < 0)) fail(fmt::format("libccd GJK intersect={} but SAT separation {:.3g}", gjk, sat.separation));
    }
    if (!err.empty()) err += cacheText(cache);
    return err;
}

/// Cold query plus full check; a failure prints the regression test.
inline void expectAgreesWithReference(const ConvexPolyhedron& a, const Pose& pose_a, const ConvexPolyhedron& b,
                                      const Pose& pose_b, CheckOptions opt = {}) {
    const ConvexMesh ma = ConvexMesh::fromPolyhedron(a), mb = ConvexMesh::fromPolyhedron(b);
    FeatureCache cache;
    const ProximityResult r = queryMeshMesh(ma, pose_a, mb, pose_b, cache);
    const std::string err = checkQuery(a, ma, pose_a, b, mb, pose_b, cache, r, opt);
    EXPECT_EQ(err, "") << regressionTest("Case", a, pose_a, b, pose_b);
}

}  // namespace vroc::native::testing
