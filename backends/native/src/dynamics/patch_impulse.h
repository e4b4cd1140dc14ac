// SPDX-License-Identifier: MIT
// Newton restitution with Coulomb friction over a whole contact patch at once: the impact of a face
// on a face (or an edge on a face) is one small linear complementarity problem over the patch's
// points, not one impulse at its centroid. Every touching point that approaches leaves at e times
// its approach speed (or more, if the rest of the patch pushes it off), no point is pulled, and one
// patch friction impulse stays inside the cone of the summed normal impulses: at the centroid while
// the patch sticks, at the normal impulses' centre of pressure when it slides.
// Why: a thin plate landing on one corner while its neighbour rises has a still centroid, so a
// centroid impulse leaves it rocking for ever; per point, the approaching corner is stopped.
// For a single point the answer is the coupled sticking / sliding impulse of newton_coulomb.h.
#pragma once

#include <span>
#include <vector>

#include "dynamics/contact.h"
#include "dynamics/impulse_result.h"
#include "dynamics/rigid_body.h"

namespace vroc::native {

/// At most this many points in a patch: a manifold's (four touching and four speculative).
constexpr int kMaxPatchPoints = static_cast<int>(kMaxManifoldSlots);

struct PatchImpulse {
    PointArray<double> normal;           ///< [N s] per point, >= 0, along n (on B; -on A)
    Vec3 tangent = Vec3::Zero();         ///< [N s] friction impulse at tangent_point, world (on B)
    Vec3 tangent_point = Vec3::Zero();   ///< [m] where the friction acts, world
    ImpulseTrouble trouble = ImpulseTrouble::None;
    bool any() const;
};

/// The impact impulses of the patch `points` [m, world] with normal `n` (A -> B) and centroid
/// `centroid` (where a sticking patch's friction acts). `restitution` per point: the approach
/// speed a point leaves with, as a fraction (0 for a plastic or resting point). Bodies are read,
/// not changed. Points that separate get no impulse unless the others would make them approach.
PatchImpulse patchImpulse(const RigidBody& a, const RigidBody& b, std::span<const Vec3> points,
                          const Vec3& centroid, const Vec3& n, std::span<const double> restitution,
                          double friction);

/// Applies `imp` to both bodies (A gets the opposite impulses).
void applyPatchImpulse(RigidBody& a, RigidBody& b, std::span<const Vec3> points, const Vec3& n,
                       const PatchImpulse& imp);

}  // namespace vroc::native
