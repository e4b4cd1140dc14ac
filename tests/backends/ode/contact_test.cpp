// SPDX-License-Identifier: MIT
// Contacts in ODE against closed forms: resting heights, Coulomb sliding distance, the material
// rule, the collision event of a bounce. Tolerances are stated per test (docs/ode-backend.md
// gives the measured values).
#include <gtest/gtest.h>

#include <cmath>

#include "ode_test_scenes.h"
#include "vroc/core/state_hash.h"

namespace vroc::test {
namespace {

constexpr double kG = 9.81;

// Centre height above 0.1 (the half size) of a 0.2 m cube released face-down 2 cm above the
// floor, e = 0, after 2 s.
double restingGap(const Shape& shape, const Vec3& at = Vec3(0, 0, 0.12), const Overrides& o = {}) {
    return restedCube(shape, at, o).pose.position.z() - 0.1;
}

TEST(OdeContact, BoxRestsOnItsFace) {
    // dCollideBoxBox: up to 4 points on the face; ERP 0.2 removes 20 % of the overlap per step.
    EXPECT_NEAR(restingGap(Shape::box(Vec3(0.1, 0.1, 0.1))), 0.0, 1e-3);
}

TEST(OdeContact, HullRestsOnItsFace) {
    // A hull is an ODE trimesh of its faces (ode.hull_geom=trimesh): box-trimesh contacts on the
    // floor, as for the box; stated tolerance 1 mm, also far from the floor's centre.
    const Shape hull = Shape::convexHull(cuboidHull(Vec3(0.1, 0.1, 0.1)));
    EXPECT_NEAR(restingGap(hull), 0.0, 1e-3);
    EXPECT_NEAR(restingGap(hull, Vec3(4, -3, 0.12)), 0.0, 1e-3) << "away from the floor's centre";
}

// A box sliding along x at v0 on mu = sqrt(0.25 x 1.0) = 0.5 stops after v0^2 / (2 mu g):
// ODE's friction pyramid has an axis along x here (dPlaneSpace of +z), so it is Coulomb's.
double slideDistance(const Vec3& direction, const Overrides& o = {}) {
    Scene scene = emptyScene(0.0, 0.25);
    const int rough = addMaterial(scene, "rough", 0.0, 1.0);
    addFloor(scene, rough);
    const int box = addBox(scene, "box", Vec3(0.1, 0.1, 0.1), 1.0, Vec3(0, 0, 0.1));
    auto backend = makeOde(scene, o);
    for (int f = 0; f < 30; ++f) backend->stepFrame(scene.frame_dt);   // settle
    BodyState s = backend->bodyState(box);
    s.linear_velocity = 3.0 * direction.normalized();
    backend->setBodyState(box, s);
    const Vec3 start = s.pose.position;
    for (int f = 0; f < 90; ++f) backend->stepFrame(scene.frame_dt);   // stops after 0.61 s
    EXPECT_LT(backend->bodyState(box).linear_velocity.norm(), 1e-3);
    return (backend->bodyState(box).pose.position - start).norm();
}

TEST(OdeContact, SlidingBoxStopsAtCoulombsDistance) {
    // Semi-implicit Euler at h = 1/60 s with a constant deceleration a = mu g: the box moves
    // h (v0 - k a h) in step k while that is positive, i.e. v0^2 / (2 a) - v0 h / 2 + O(a h^2).
    const double a = 0.5 * kG, h = 1.0 / 60, v0 = 3.0;
    double discrete = 0.0;
    for (int k = 1; v0 - k * a * h > 0; ++k) discrete += h * (v0 - k * a * h);
    const double continuous = v0 * v0 / (2 * a);
    const double d = slideDistance(Vec3::UnitX());
    EXPECT_NEAR(d, discrete, 0.005 * discrete);
    EXPECT_NEAR(d, continuous, 0.03 * continuous);
    // With friction axes along the sliding velocity the diagonal meets mu N too (ODE's default
    // dPlaneSpace axes give sqrt(2) mu N there: docs/ode-backend.md).
    const double diagonal = slideDistance(Vec3(1, 1, 0), {{"ode.friction_axes", "sliding"}});
    EXPECT_NEAR(diagonal, discrete, 0.005 * discrete);
}

TEST(OdeContact, MaterialRuleIsMinAndGeometricMean) {
    // (e 0.2 vs 0.9, mu 0.25 vs 1.0) must run bit-identically to (0.2, 0.5) on both sides.
    auto run = [](double ea, double mua, double eb, double mub) {
        Scene scene = emptyScene(ea, mua);
        const int other = addMaterial(scene, "other", eb, mub);
        addFloor(scene, other);
        const int ball = addBall(scene, "ball", 0.1, 1.0, Vec3(0, 0, 0.6));
        scene.bodies[ball].linear_velocity = Vec3(2, 0, 0);
        scene.bodies[ball].angular_velocity = Vec3(0, 0, 3);
        auto b = makeOde(scene);
        for (int f = 0; f < 120; ++f) b->stepFrame(scene.frame_dt);
        return stateHash(*b);
    };
    EXPECT_EQ(run(0.2, 0.25, 0.9, 1.0), run(0.2, 0.5, 0.2, 0.5));
    EXPECT_EQ(run(0.9, 1.0, 0.2, 0.25), run(0.2, 0.5, 0.2, 0.5));
}

TEST(OdeContact, FirstBounceIsOneEventWithTheCollisionImpulse) {
    const double e = 0.5, m = 2.0;
    Scene scene = emptyScene(e, 0.5);
    addFloor(scene);
    const int ball = addBall(scene, "ball", 0.1, m, Vec3(0.2, -0.1, 1.1));
    auto backend = makeOde(scene);
    std::vector<CollisionEvent> events;
    for (int f = 0; f < 40; ++f) {   // the ball lands after 0.45 s
        backend->stepFrame(scene.frame_dt);
        for (const CollisionEvent& ev : backend->takeEvents()) events.push_back(ev);
    }
    ASSERT_EQ(events.size(), 1u);
    const CollisionEvent& ev = events[0];
    EXPECT_EQ(ev.body_a, 0);
    EXPECT_EQ(ev.body_b, ball);
    EXPECT_LT((ev.normal - Vec3::UnitZ()).norm(), 1e-9) << "from the floor (a) to the ball (b)";
    EXPECT_NEAR(ev.point.x(), 0.2, 1e-6);
    EXPECT_NEAR(ev.point.y(), -0.1, 1e-6);
    // ODE resolves the bounce in one step: m (1 + e) v (+ the step's gravity), v = sqrt(2 g h).
    const double ideal = m * (1 + e) * std::sqrt(2 * kG * 1.0);
    EXPECT_NEAR(ev.impulse, ideal, 0.1 * ideal);
    EXPECT_EQ(backend->statistics().at("collision_events"), 1.0);
}

}  // namespace
}  // namespace vroc::test
