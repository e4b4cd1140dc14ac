// SPDX-License-Identifier: MIT
// Carried manifolds (manifold_anchor.h) against the narrow phase run again at the moved poses, and
// the motion bound against every vertex moved by brute force.
#include <random>

#include "backend/body_shape.h"
#include "backend/part_query.h"
#include "narrowphase/contact_patch.h"
#include "narrowphase/manifold_anchor.h"
#include "narrowphase_check.h"

namespace vroc::native::testing {
namespace {

/// A box B resting on a slab A, 0.3 mm above it, its bottom face fully inside A's top face.
struct Resting {
    ConvexMesh a = ConvexMesh::box(Vec3(1, 1, 0.5));
    ConvexMesh b = ConvexMesh::box(Vec3(0.2, 0.15, 0.1));
    Pose fa{Vec3(0.3, -0.2, 0.1), Quat(Eigen::AngleAxisd(0.4, Vec3(0.2, 0.1, 1).normalized()))};
    Pose fb;
    Resting() {
        const Pose rel{Vec3(0.1, 0.05, 0.5 + 0.1 + 3e-4), Quat(Eigen::AngleAxisd(0.3, Vec3::UnitZ()))};
        fb = fa * rel;
    }
    /// The manifold as the backend builds it without a reach: the patch's points, one distance.
    ContactManifold query(const Pose& pa, const Pose& pb) const {
        FeatureCache cache;
        const ProximityResult r = queryMeshMesh(a, pa, b, pb, cache);
        const ContactPatch patch = contactPatch(a, pa, b, pb, cache, r, 1e-3);
        ContactManifold m;
        m.normal = r.normal;
        m.distance = r.distance;
        m.centroid = patch.centroid;
        for (const Vec3& p : patch.points) m.points.push_back(p);
        return m;
    }
};

Pose smallMotion(std::mt19937& rng, double shift, double angle) {
    std::normal_distribution<double> n(0.0, 1.0);
    const Vec3 axis = Vec3(n(rng), n(rng), n(rng)).normalized();
    const Vec3 dir = Vec3(n(rng), n(rng), n(rng)).normalized();
    return Pose{shift * dir, Quat(Eigen::AngleAxisd(angle, axis))};
}

TEST(NarrowphaseManifoldAnchor, ATranslatedPairCarriesItsDistanceExactly) {
    const Resting s;
    const ContactManifold m0 = s.query(s.fa, s.fb);
    ASSERT_EQ(m0.points.size(), 4u);
    ManifoldAnchor anchor;
    anchorManifold(m0, s.fa, s.fb, 1e-3, anchor);
    // B slides 40 um and sinks 20 um along A's normal: the face-face distance changes by exactly that.
    const Vec3 move = s.fa.rotate(Vec3(4e-5, -1e-5, -2e-5));
    const Pose fb{s.fb.position + move, s.fb.orientation};
    ContactManifold carried;
    ASSERT_TRUE(carryManifold(anchor, s.fa, fb, carried));
    const ContactManifold queried = s.query(s.fa, fb);
    EXPECT_NEAR(carried.distance, queried.distance, 1e-12);
    EXPECT_NEAR(carried.distance, 3e-4 - 2e-5, 1e-12);
    EXPECT_NEAR((carried.normal - queried.normal).norm(), 0.0, 1e-12);
    // Both bodies moved together (any rigid motion of the pair): nothing changes but the frame.
    const Pose g{Vec3(0.5, -1, 2), Quat(Eigen::AngleAxisd(1.1, Vec3(1, 2, 3).normalized()))};
    ASSERT_TRUE(carryManifold(anchor, g * s.fa, g * s.fb, carried));
    EXPECT_NEAR(carried.distance, m0.distance, 1e-12);
    for (std::size_t k = 0; k < m0.points.size(); ++k)
        EXPECT_NEAR((carried.points[k] - g.apply(m0.points[k])).norm(), 0.0, 1e-12);
}

TEST(NarrowphaseManifoldAnchor, SmallTurnsAreCarriedToSecondOrder) {
    // Random relative motions of size d (a shift of d and a turn of d / 0.25 m): the carried
    // distance differs from a new query by a second-order term, far below d itself.
    const Resting s;
    const ContactManifold m0 = s.query(s.fa, s.fb);
    ManifoldAnchor anchor;
    anchorManifold(m0, s.fa, s.fb, 1e-3, anchor);
    std::mt19937 rng(7);
    for (double d : {1e-6, 1e-5, 2e-5}) {
        double worst = 0.0;
        for (int trial = 0; trial < 100; ++trial) {
            const Pose fb = s.fb * smallMotion(rng, d, d / 0.25);
            ContactManifold carried;
            if (!carryManifold(anchor, s.fa, fb, carried)) continue;
            const ContactManifold queried = s.query(s.fa, fb);
            worst = std::max(worst, std::abs(carried.distance - queried.distance));
        }
        EXPECT_LT(worst, 1e-3 * d) << "d = " << d;
    }
}

TEST(NarrowphaseManifoldAnchor, TheMotionBoundHoldsForEveryVertexNearEitherBody) {
    // Brute force: every vertex of B, in A's frame, before and after a random motion of both
    // bodies. A vertex within both radius_a of A's origin and radius_b of B's (where a contact
    // lies) moves at most the bound.
    const Resting s;
    ContactManifold m0 = s.query(s.fa, s.fb);
    ManifoldAnchor anchor;
    anchorManifold(m0, s.fa, s.fb, 1e-3, anchor);
    double radius_b = 0.0;
    for (int v = 0; v < s.b.vertexCount(); ++v) radius_b = std::max(radius_b, s.b.position(v).norm());
    std::mt19937 rng(11);
    for (int trial = 0; trial < 200; ++trial) {
        const Pose fa = s.fa * smallMotion(rng, 1e-3, 0.01), fb = s.fb * smallMotion(rng, 1e-3, 0.01);
        for (double radius_a : {0.75, 1e3}) {
            const double bound = anchoredMotion(anchor, fa, fb, radius_a, radius_b);
            double moved = 0.0;
            for (int v = 0; v < s.b.vertexCount(); ++v) {
                const Vec3 before = s.fa.applyInverse(s.fb.apply(s.b.position(v)));
                const Vec3 after = fa.applyInverse(fb.apply(s.b.position(v)));
                if (before.norm() <= radius_a) moved = std::max(moved, (after - before).norm());
            }
            // radius_b covers every vertex; radius_a = 1000 m too, 0.5 m some of them.
            EXPECT_LE(moved, bound * (1 + 1e-12) + 1e-15);
        }
    }
    // A box turning on a large floor: bounded by the box's size, not the floor's.
    const Pose floor{}, box{Vec3(50, 0, 0.5), Quat::Identity()};
    ContactManifold m;
    m.points.push_back(Vec3(50, 0, 0));
    m.distance = 0.0;
    ManifoldAnchor far;
    anchorManifold(m, floor, box, 1e-3, far);
    const Pose turned{Vec3(50, 0, 0.5), Quat(Eigen::AngleAxisd(1e-4, Vec3::UnitZ()))};
    EXPECT_LT(anchoredMotion(far, floor, turned, 1e4, 0.9), 1e-4);
}

TEST(NarrowphaseManifoldAnchor, APartingOrSinkingPairIsLeftToAQuery) {
    const Resting s;
    const ContactManifold m0 = s.query(s.fa, s.fb);
    ManifoldAnchor anchor;
    anchorManifold(m0, s.fa, s.fb, 1e-3, anchor);
    ContactManifold m;
    const Vec3 up = s.fa.rotate(Vec3::UnitZ());
    EXPECT_FALSE(carryManifold(anchor, s.fa, Pose{s.fb.position + 8e-4 * up, s.fb.orientation}, m));   // 1.1 mm: out of the window
    EXPECT_FALSE(carryManifold(anchor, s.fa, Pose{s.fb.position - 4e-4 * up, s.fb.orientation}, m));   // -0.1 mm: penetrating
    EXPECT_TRUE(carryManifold(anchor, s.fa, Pose{s.fb.position + 5e-4 * up, s.fb.orientation}, m));
    EXPECT_NEAR(m.distance, 8e-4, 1e-12);
}

TEST(NarrowphaseManifoldAnchor, APartsBoxGapIsALowerBoundOnItsDistance) {
    // gapToBall (compound pairs skip far part pairs by it) against the narrow phase's distance
    // between the part and a sphere, at random poses.
    const Shape slab = [] {
        Shape sh;
        sh.kind = Shape::Kind::Box;
        sh.half_extents = Vec3(0.05, 0.75, 0.16);
        return sh;
    }();
    const BodyShape shape = BodyShape::fromScene(slab, Vec3::Zero());
    const ConvexPart& part = shape.parts.front();
    EXPECT_NEAR(part.bound_radius, Vec3(0.05, 0.75, 0.16).norm(), 1e-12);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    int far = 0;
    for (int trial = 0; trial < 500; ++trial) {
        const Pose world{Vec3(u(rng), u(rng), u(rng)), Quat(Eigen::AngleAxisd(u(rng), Vec3(u(rng), u(rng), 1).normalized()))};
        const Vec3 c(u(rng), u(rng), u(rng));
        const double r = 0.1;
        FeatureCache cache;
        ConvexPart ball;
        ball.is_sphere = true;
        ball.radius = r;
        const ProximityResult exact = queryParts(part, world, ball, Pose{c, Quat::Identity()}, cache);
        const double bound = part.gapToBall(world, c, r);
        EXPECT_LE(bound, exact.distance + 1e-12);
        if (bound > 0.5 * exact.distance && exact.distance > 0.1) ++far;
    }
    EXPECT_GT(far, 100);   // and not a vacuous bound
}

}  // namespace
}  // namespace vroc::native::testing
