// SPDX-License-Identifier: MIT
// vertexApproachTime: closed forms where the bound is exact, the case it exists for (a box tipping
// over an edge on a floor), and a property test: random spinning, torqued boxes moved by the
// backend's own integrators (the drift's split kick and torque-free rotation), whose projected
// separation is measured at dense times up to the bound and must never fall below the floor.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "dynamics/free_flight.h"
#include "dynamics/rigid_body.h"
#include "geometry/convex_mesh.h"
#include "scheduling/collision_time_bound.h"
#include "scheduling/vertex_approach_bound.h"

namespace vroc::native {
namespace {

RigidBody boxBody(const Vec3& half, double mass) {
    RigidBody rb;
    rb.is_static = false;
    rb.inv_mass = 1.0 / mass;
    const Vec3 e = half * 2.0;
    const Vec3 diag(mass / 12.0 * (e.y() * e.y() + e.z() * e.z()), mass / 12.0 * (e.x() * e.x() + e.z() * e.z()),
                    mass / 12.0 * (e.x() * e.x() + e.y() * e.y()));
    rb.inertia_body = diag.asDiagonal();
    rb.inv_inertia_body = diag.cwiseInverse().asDiagonal();
    Vec3 moments = diag;
    std::sort(moments.data(), moments.data() + 3);
    rb.principal_moments = moments;
    rb.isotropic = diag.maxCoeff() - diag.minCoeff() <= 1e-12 * diag.maxCoeff();
    return rb;
}

SupportPoints vertices(const ConvexMesh& mesh, const RigidBody& rb) {
    SupportPoints s;
    for (int v = 0; v < mesh.vertexCount(); ++v) s.points.push_back(rb.framePose().apply(mesh.position(v)));
    return s;
}

// A body's motion as the backend moves it: a drift (constant acceleration and torque, the torque's
// impulse half before and half after a torque-free rotation) from t = 0 over `t`.
struct Drift {
    Vec3 acceleration = Vec3::Zero();
    Vec3 torque = Vec3::Zero();
};

RigidBody movedBy(RigidBody rb, const Drift& d, double t) {
    rb.com += rb.velocity * t + (0.5 * t * t) * d.acceleration;
    rb.velocity += d.acceleration * t;
    rb.angular_momentum += (0.5 * t) * d.torque;
    rb.refreshEnergy();
    advanceTorqueFree(rb, t);
    rb.angular_momentum += (0.5 * t) * d.torque;
    rb.refreshEnergy();
    return rb;
}

RigidMotion motionOf(const RigidBody& rb, const Drift& d, double horizon) {
    RigidMotion m;
    m.com = rb.com;
    m.velocity = rb.velocity;
    m.acceleration = d.acceleration;
    m.angular_velocity = rb.angularVelocity();
    m.curvature = rotationCurvatureBound(rb.angular_momentum.norm(), d.torque.norm(), rb.smallestMoment(), horizon,
                                         rb.isotropic);
    return m;
}

// σ = min over B of n·y − max over A of n·x (pads included), from the actual points.
double projectedGap(const SupportPoints& a, const SupportPoints& b, const Vec3& n) {
    double top_a = -kNever, low_b = kNever;
    for (const Vec3& p : a.points) top_a = std::max(top_a, n.dot(p) + a.pad);
    for (const Vec3& p : b.points) low_b = std::min(low_b, n.dot(p) - b.pad);
    return low_b - top_a;
}

TEST(SchedulingVertexApproachBound, TranslationAloneIsExact) {
    // A cube falling at 2 m/s with no spin onto a static floor 3 mm below: it reaches the floor
    // level 1 mm (floor = 1 mm) after exactly 1 ms (less the bound's relative pull-back of 1e-9).
    const ConvexMesh cube = ConvexMesh::box(Vec3::Constant(0.1));
    RigidBody box = boxBody(Vec3::Constant(0.1), 1.0);
    box.com = Vec3(0, 0, 0.103);
    box.velocity = Vec3(0.3, 0, -2.0);
    const SupportPoints a = vertices(cube, box);
    SupportPoints floor;
    floor.points = {Vec3(-5, -5, 0), Vec3(5, -5, 0), Vec3(0, 5, 0)};
    const RigidMotion moving = motionOf(box, {}, 1.0);
    const Vec3 down(0, 0, -1);   // from the box (A) towards the floor (B)
    EXPECT_NEAR(vertexApproachTime(a, moving, floor, RigidMotion::stationary(Vec3::Zero()), down, 0.001, 1.0), 1e-3,
                2e-12);
    EXPECT_EQ(vertexApproachTime(a, moving, floor, RigidMotion::stationary(Vec3::Zero()), down, 0.001, 5e-4), kNever);
    EXPECT_EQ(vertexApproachTime(a, moving, floor, RigidMotion::stationary(Vec3::Zero()), down, 0.004, 1.0), 0.0);
    // A sphere is its centre padded by the radius.
    SupportPoints ball{{Vec3(0, 0, 0.105)}, 0.1};
    RigidMotion falling = RigidMotion::stationary(Vec3(0, 0, 0.105));
    falling.velocity = Vec3(0, 0, -1.0);
    EXPECT_NEAR(vertexApproachTime(ball, falling, floor, RigidMotion::stationary(Vec3::Zero()), down, 0.001, 1.0), 4e-3,
                1e-11);
}

TEST(SchedulingVertexApproachBound, TippingBoxOutlastsThePairBound) {
    // A 0.4 x 0.2 x 0.2 m box pivoting about its bottom edge at 5 rad/s, the edge 0.5 mm above a
    // static floor and at rest there (the solver holds it): the pair bound (|ω| R on the 0.5 mm gap)
    // gives it about 0.2 ms before it could reach the floor; the per-vertex bound sees the pivot at
    // rest and the far edge 14 cm up.
    const Vec3 half(0.2, 0.1, 0.1);
    const ConvexMesh mesh = ConvexMesh::box(half);
    RigidBody box = boxBody(half, 2.0);
    const double tilt = 0.6;   // [rad] about the y axis: the +x bottom edge is the lowest
    box.orientation = Quat(Eigen::AngleAxisd(tilt, Vec3::UnitY()));
    const Vec3 pivot_local(0.2, 0.0, -0.1);
    const double lift = 0.0005 - (box.orientation * pivot_local).z();
    box.com = Vec3(0, 0, lift);
    const Vec3 omega(0, -5.0, 0);   // falling back flat about the pivot edge
    box.angular_momentum = box.rotation() * box.inertia_body * box.rotation().transpose() * omega;
    box.velocity = -omega.cross(box.orientation * pivot_local - Vec3::Zero());   // the pivot at rest
    box.refreshEnergy();
    const SupportPoints a = vertices(mesh, box);
    SupportPoints floor;
    floor.points = {Vec3(-5, -5, 0), Vec3(5, -5, 0), Vec3(0, 5, 0)};
    const Vec3 down(0, 0, -1);
    const double floor_gap = -0.0005;   // a held pair may close to -cd/2
    const double h = 1.0 / 60.0;
    const RigidMotion m = motionOf(box, {}, h);
    const double per_vertex = vertexApproachTime(a, m, floor, RigidMotion::stationary(Vec3::Zero()), down, floor_gap, h);
    MotionBound pair;
    pair.velocity = box.velocity;
    // The pair bound as this test was written against: |L| / I_min (the body's own bound is now the
    // tighter torqueFreeSpeedBound, which gives the pair 0.57 ms, 9x less than the per-vertex bound).
    pair.angular_speed = box.angular_momentum.norm() / box.smallestMoment();
    pair.outer_radius = half.norm();
    pair.inner_radius = half.minCoeff();
    const double pair_time = earliestCollisionTime(0.0005 - floor_gap, down, pair, MotionBound::stationary(), h);
    EXPECT_LT(pair_time, 3e-4);
    EXPECT_GT(per_vertex, 10.0 * pair_time);
    // And it holds: the box turned by the integrator never dips below the floor level before then.
    const double until = std::min(per_vertex, h);
    for (int k = 0; k <= 400; ++k) {
        const double t = until * k / 400.0;
        EXPECT_GE(projectedGap(vertices(mesh, movedBy(box, {}, t)), floor, down), floor_gap) << "t = " << t;
    }
}

TEST(SchedulingVertexApproachBound, NeverLaterThanTheIntegratedMotion) {
    std::mt19937_64 rng(20261202);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    auto unit = [&] {
        Vec3 v(u(rng), u(rng), u(rng));
        while (v.norm() < 0.1) v = Vec3(u(rng), u(rng), u(rng));
        return v.normalized();
    };
    int tested = 0, positive = 0;
    double shortest_ratio = kNever;
    for (int trial = 0; trial < 300; ++trial) {
        const Vec3 ha(0.05 + 0.15 * std::abs(u(rng)), 0.05 + 0.15 * std::abs(u(rng)), 0.05 + 0.15 * std::abs(u(rng)));
        const Vec3 hb = trial % 3 == 0 ? Vec3::Constant(0.12) : Vec3(0.05 + 0.15 * std::abs(u(rng)), 0.1, 0.07);
        const ConvexMesh mesh_a = ConvexMesh::box(ha), mesh_b = ConvexMesh::box(hb);
        RigidBody a = boxBody(ha, 1.0 + std::abs(u(rng))), b = boxBody(hb, 1.0 + std::abs(u(rng)));
        a.orientation = Quat(Eigen::AngleAxisd(3.0 * u(rng), unit()));
        b.orientation = Quat(Eigen::AngleAxisd(3.0 * u(rng), unit()));
        const Vec3 n = unit();
        a.com = Vec3::Zero();
        b.com = Vec3::Zero();
        // Place B beyond A along n, its projected gap 0..5 mm.
        const double gap0 = 0.005 * std::abs(u(rng));
        b.com = n * (gap0 - projectedGap(vertices(mesh_a, a), vertices(mesh_b, b), n));
        for (RigidBody* rb : {&a, &b}) {
            rb->velocity = 2.0 * Vec3(u(rng), u(rng), u(rng));
            const Vec3 w = 10.0 * Vec3(u(rng), u(rng), u(rng));
            rb->angular_momentum = rb->rotation() * rb->inertia_body * rb->rotation().transpose() * w;
            rb->refreshEnergy();
        }
        const Drift da{Vec3(0, 0, -9.81) + 20.0 * Vec3(u(rng), u(rng), u(rng)), 0.5 * Vec3(u(rng), u(rng), u(rng))};
        const Drift db{Vec3(0, 0, -9.81), trial % 2 == 0 ? Vec3::Zero() : Vec3(0.3 * u(rng), 0.2, 0.0)};
        const double horizon = 1.0 / 60.0;
        const double floor = gap0 - 0.002 * std::abs(u(rng)) - 1e-5;
        const double t_bound = vertexApproachTime(vertices(mesh_a, a), motionOf(a, da, horizon), vertices(mesh_b, b),
                                                  motionOf(b, db, horizon), n, floor, horizon);
        ++tested;
        if (t_bound > 0.0) ++positive;
        const double until = std::min(t_bound, horizon);
        double first_below = kNever;
        for (int k = 0; k <= 200; ++k) {
            const double t = until * k / 200.0;
            const double sigma =
                projectedGap(vertices(mesh_a, movedBy(a, da, t)), vertices(mesh_b, movedBy(b, db, t)), n);
            ASSERT_GE(sigma, floor - 1e-12) << "trial " << trial << ": at t = " << t << " of the bound " << t_bound;
        }
        // How tight: the first time the integrated motion actually reaches the floor, if it does.
        for (int k = 1; k <= 400 && t_bound < horizon; ++k) {
            const double t = horizon * k / 400.0;
            if (projectedGap(vertices(mesh_a, movedBy(a, da, t)), vertices(mesh_b, movedBy(b, db, t)), n) < floor) {
                first_below = t;
                break;
            }
        }
        if (first_below < kNever && t_bound > 0.0) shortest_ratio = std::min(shortest_ratio, t_bound / first_below);
    }
    EXPECT_EQ(tested, 300);
    EXPECT_GT(positive, 250);   // a claim is made nearly always (0 only when nothing can be said)
    EXPECT_GT(shortest_ratio, 0.05);
}

TEST(SchedulingVertexApproachBound, CurvatureBoundCoversEulersEquation) {
    EXPECT_EQ(rotationCurvatureBound(0.0, 0.0, 1.0, 1.0, false), 0.0);
    // Ω = |L| / I_min = 2, |ω̇| ≤ Ω |L| / I_min = 4: K = 8; isotropic: |ω̇| = 0, K = 4.
    EXPECT_DOUBLE_EQ(rotationCurvatureBound(2.0, 0.0, 1.0, 1.0, false), 8.0);
    EXPECT_DOUBLE_EQ(rotationCurvatureBound(2.0, 0.0, 1.0, 1.0, true), 4.0);
    // A torque of 1 N m over 1 s: L_max = 3, Ω = 3, |ω̇| ≤ 1 + 9.
    EXPECT_DOUBLE_EQ(rotationCurvatureBound(2.0, 1.0, 1.0, 1.0, false), 19.0);
    EXPECT_EQ(rotationCurvatureBound(1.0, 0.0, 0.0, 1.0, false), kNever);
}

}  // namespace
}  // namespace vroc::native
