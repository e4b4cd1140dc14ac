// SPDX-License-Identifier: MIT
#include "backend/part_query.h"

#include <utility>

namespace vroc::native {

ProximityResult queryParts(const ConvexPart& pa, const Pose& fa, const ConvexPart& pb,
                           const Pose& fb, FeatureCache& cache) {
    if (pa.is_sphere && pb.is_sphere) {
        return querySphereSphere(fa.position, pa.radius, fb.position, pb.radius);
    }
    if (pa.is_sphere) return querySphereMesh(fa.position, pa.radius, *pb.mesh, fb, cache);
    if (pb.is_sphere) {
        // The narrow phase puts the sphere first: swap back so A stays A.
        ProximityResult r = querySphereMesh(fb.position, pb.radius, *pa.mesh, fa, cache);
        std::swap(r.point_a, r.point_b);
        r.normal = -r.normal;
        return r;
    }
    return queryMeshMesh(*pa.mesh, fa, *pb.mesh, fb, cache);
}

void partPatch(const ConvexPart& pa, const Pose& fa, const ConvexPart& pb, const Pose& fb, const FeatureCache& cache,
               const ProximityResult& r, double tolerance, double reach, ContactPatch& p) {
    if (!pa.is_sphere && !pb.is_sphere) {
        contactPatch(*pa.mesh, fa, *pb.mesh, fb, cache, r, tolerance, reach, p);
        return;
    }
    p.points.clear();
    p.gaps.clear();
    p.centroid = 0.5 * (r.point_a + r.point_b);
    p.points.push_back(p.centroid);
    p.gaps.push_back(r.distance);
}

}  // namespace vroc::native
