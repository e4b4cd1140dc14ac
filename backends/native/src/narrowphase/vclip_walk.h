// SPDX-License-Identifier: MIT
// The V-Clip closest-feature walk (Mirtich 1998) between two convex meshes: states V-V, V-E,
// E-E, V-F and E-F, edges clipped against Voronoi planes, derivative signs choosing the next
// feature, the V-F local minimum escaped by an O(n) face scan. No tolerances: every test is an
// exact sign of a computed quantity. See docs/native-narrowphase.md for the termination argument.
#pragma once

#include "geometry/convex_mesh.h"
#include "narrowphase/proximity.h"
#include "narrowphase/relative_frame.h"

namespace vroc::native {

enum class WalkOutcome : std::uint8_t {
    Separated,     ///< features a, b are a closest pair, distance > 0 (or exactly touching, = 0)
    Penetrating,   ///< the bodies touch or overlap (edge through face, V-F scan, zero distance)
    StepLimit,     ///< the hard step bound was hit (never expected; the caller counts a warning)
};

struct WalkResult {
    WalkOutcome outcome = WalkOutcome::StepLimit;
    Feature a, b;                 ///< final features (the cache for the next query)
    int steps = 0;                ///< feature transitions taken
    Vec3 point_a = Vec3::Zero();  ///< [m] closest point on a, in A's frame (Separated only)
    Vec3 point_b = Vec3::Zero();  ///< [m] closest point on b, in A's frame (Separated only)
    double distance = 0.0;        ///< [m] |point_a - point_b| (Separated only)
};

/// Runs the walk from (fa, fb). `b_to_a` maps B-local to A-local coordinates.
/// `max_steps` is the hard bound (stepBound() gives the default).
WalkResult vclipWalk(const ConvexMesh& a, const ConvexMesh& b, const RelativeFrame& b_to_a,
                     Feature fa, Feature fb, int max_steps);

/// A step bound far above any walk V-Clip takes (it is monotone in (distance, dimension)), but
/// finite so a floating-point cycle cannot hang a step: 4 (E_a + E_b) + 64.
int stepBound(const ConvexMesh& a, const ConvexMesh& b);

/// A starting pair without history: the vertices extreme towards each other's centroid.
FeatureCache seedFeatures(const ConvexMesh& a, const ConvexMesh& b, const RelativeFrame& b_to_a);

}  // namespace vroc::native
