// SPDX-License-Identifier: MIT
// The narrow-phase contract of the native backend: closest features between two convex shapes,
// with interframe coherence (the cached feature pair), penetration detected and measured.
// Everything here is in world coordinates unless a name says otherwise.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "vroc/core/convex_polyhedron.h"
#include "vroc/core/math.h"

namespace vroc::native {

class ConvexMesh;   // half-edge polyhedron with Voronoi planes (convex_mesh.h); immutable, shared

/// The kind of a feature on a convex mesh.
enum class FeatureType : std::uint8_t { Vertex, Edge, Face, None };

struct Feature {
    FeatureType type = FeatureType::None;
    int index = -1;   ///< vertex index, half-edge index, or face index in the ConvexMesh
};

/// Kept per pair between queries (interframe coherence). A default-constructed cache means
/// "no history": the query seeds itself.
struct FeatureCache {
    Feature a;
    Feature b;
};

struct ProximityResult {
    double distance = 0.0;        ///< [m] signed: > 0 separated, <= 0 penetrating (-depth)
    Vec3 point_a = Vec3::Zero();  ///< [m] closest point on A (deepest point when penetrating)
    Vec3 point_b = Vec3::Zero();  ///< [m] closest point on B
    Vec3 normal = Vec3::UnitX();  ///< unit, from A towards B (separating / minimum-translation direction)
    bool penetrating = false;
    int walk_steps = 0;           ///< feature transitions taken by this query
    bool converged = true;        ///< false: step bound hit, result from the fallback (counted warning)
};

/// Closest features of two convex meshes (V-Clip-style walk, cache updated in place).
ProximityResult queryMeshMesh(const ConvexMesh& a, const Pose& pose_a,
                              const ConvexMesh& b, const Pose& pose_b, FeatureCache& cache);

/// Sphere (centre in world, radius [m]) against a convex mesh: exact, no tessellation.
/// The sphere is A: the normal points from the sphere towards the mesh.
ProximityResult querySphereMesh(const Vec3& center, double radius,
                                const ConvexMesh& mesh, const Pose& pose, FeatureCache& cache);

/// Sphere A against sphere B.
ProximityResult querySphereSphere(const Vec3& center_a, double radius_a,
                                  const Vec3& center_b, double radius_b);

}  // namespace vroc::native
