// SPDX-License-Identifier: MIT
// A touching pair's last queried manifold, anchored on both bodies, so that while the two bodies
// barely move relative to each other the pair need not be queried and clipped again: each point's
// separation is carried along by the bodies' relative motion (the relative anchors of Box2D v3's
// contact solver), the normal and the points turn with body A (docs/native-narrowphase.md,
// "Carried manifolds").
#pragma once

#include "dynamics/contact.h"
#include "vroc/core/math.h"

namespace vroc::native {

struct ManifoldAnchor {
    bool valid = false;
    Pose relative;                 ///< B's scene frame in A's at the query
    double window = 0.0;           ///< [m] the window the manifold was built with
    double distance = 0.0;         ///< [m] closest distance at the query
    Vec3 normal_a = Vec3::UnitZ(); ///< normal in A's frame
    Vec3 centroid_a = Vec3::Zero();///< centroid in A's frame
    PointArray<Vec3> on_a;         ///< each point in A's frame
    PointArray<Vec3> on_b;         ///< each point in B's frame
    PointArray<double> gap;        ///< per point (empty: every point at `distance`)
};

/// Anchors `m` (queried at A's and B's scene frames `fa`, `fb`, within `window`) on both bodies.
void anchorManifold(const ContactManifold& m, const Pose& fa, const Pose& fb, double window, ManifoldAnchor& out);

/// [m] Bound on how far B's material near the contact moved in A's frame since the anchor. The
/// relative motion is a turn by θ and a shift; a point within `radius_a` of A's frame origin moved
/// at most |shift at A's origin| + θ radius_a, one within `radius_b` of B's at most
/// |shift of B's origin| + θ radius_b. The contact lies within both, so the smaller bound holds (a
/// box turning on a large floor is bounded by its own size, not the floor's).
double anchoredMotion(const ManifoldAnchor& anchor, const Pose& fa, const Pose& fb, double radius_a, double radius_b);

/// The anchored manifold at `fa`, `fb` now, into `m` (geometry only: points on A, normal and
/// centroid turned with A, each gap moved by the normal displacement of its two anchors; the
/// distance is the smallest change added to the queried distance). Returns false, leaving `m`
/// unspecified, if the carried distance leaves [0, window): a query must decide then.
bool carryManifold(const ManifoldAnchor& anchor, const Pose& fa, const Pose& fb, ContactManifold& m);

}  // namespace vroc::native
