// SPDX-License-Identifier: MIT
// Closest features of two convex parts of two bodies, dispatched to the exact narrow-phase query
// (sphere–sphere, sphere–mesh, mesh–mesh), with A always the lower body index.
#pragma once

#include "backend/body_shape.h"
#include "narrowphase/contact_patch.h"

namespace vroc::native {

/// Proximity of part `pa` posed at world `fa` (part frame -> world) and part `pb` at `fb`.
/// The normal points from A to B. `cache` is the part pair's feature cache (updated).
ProximityResult queryParts(const ConvexPart& pa, const Pose& fa, const ConvexPart& pb,
                           const Pose& fb, FeatureCache& cache);

/// Contact region of a touching part pair (world): the patch polygon for two meshes, the single
/// mid-point otherwise; into `patch` (cleared first, its storage kept).
void partPatch(const ConvexPart& pa, const Pose& fa, const ConvexPart& pb, const Pose& fb, const FeatureCache& cache,
               const ProximityResult& r, double tolerance, double reach, ContactPatch& patch);

}  // namespace vroc::native
