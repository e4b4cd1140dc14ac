// SPDX-License-Identifier: MIT
// The contact phase's block solve of a patch: one sweep gives the minimum-norm normal impulses that
// stop every point's approach, checked against the pseudo-inverse of the explicitly assembled
// 12-dof system (J W J^T, solved by SVD), for patches of 2, 3 and 4 points, collinear ones included;
// a sticking patch alone on its bodies solved whole (normals, friction and spin friction in one
// solve) against the same system with the friction rows added; and which islands count as cold
// (the extra sweeps of a first solve).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include <Eigen/SVD>

#include "dynamics/contact_solver.h"
#include "native_test_scenes.h"

namespace vroc::native::test {
namespace {

struct Case {
    std::vector<RigidBody> bodies;
    ContactManifold manifold;
};

// Two random bodies meeting over a patch of `count` points spread around `centre` in the plane
// normal to n (with small offsets along n), B approaching A along -n at about 1 m/s.
Case randomPatch(std::mt19937_64& rng, int count, bool collinear, bool a_static) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Case c;
    c.bodies = {randomBody(rng, a_static), randomBody(rng)};
    const Vec3 n = Vec3(u(rng), u(rng), u(rng)).normalized();
    const Vec3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
    // The bodies on either side of the patch, their centres of mass a little off its axis.
    const Vec3 centre = c.bodies[0].com;
    c.bodies[0].com = centre - 0.3 * n + 0.05 * (u(rng) * t1 + u(rng) * t2);
    c.bodies[1].com = centre + 0.3 * n + 0.05 * (u(rng) * t1 + u(rng) * t2);
    ContactManifold& m = c.manifold;
    m.body_a = 0;
    m.body_b = 1;
    m.pair = 0;
    m.normal = n;
    for (int i = 0; i < count; ++i) {
        const double x = u(rng) * 0.3, y = collinear ? 0.5 * x : u(rng) * 0.3;
        m.points.push_back(centre + x * t1 + y * t2 + 1e-4 * u(rng) * n);
    }
    m.centroid = Vec3::Zero();
    for (const Vec3& p : m.points) m.centroid += p;
    m.centroid /= static_cast<double>(count);
    if (a_static) c.bodies[0].velocity.setZero();
    c.bodies[1].velocity = c.bodies[0].velocity - (1.0 + 0.2 * u(rng)) * n;
    for (RigidBody& b : c.bodies) b.angular_momentum *= b.is_static ? 0.0 : 0.05;
    return c;
}

// The two bodies' 12-dof velocities u and inverse mass w (a static body's: zero).
void twoBodies(const Case& c, Eigen::VectorXd& u, Eigen::MatrixXd& w) {
    u.resize(12);
    w = Eigen::MatrixXd::Zero(12, 12);
    for (int k = 0; k < 2; ++k) {
        const RigidBody& b = c.bodies[static_cast<std::size_t>(k)];
        u.segment<3>(6 * k) = b.velocity;
        u.segment<3>(6 * k + 3) = b.is_static ? Vec3::Zero() : b.angularVelocity();
        w.block<3, 3>(6 * k, 6 * k) = b.inv_mass * Mat3::Identity();
        w.block<3, 3>(6 * k + 3, 6 * k + 3) = b.is_static ? Mat3::Zero() : b.invInertiaWorld();
    }
}

// The minimum-norm impulses that bring each point's normal relative velocity to zero:
// x = (J W J^T)^+ (-J u), with J the points' 12-dof normal Jacobians.
Eigen::VectorXd referenceImpulses(const Case& c) {
    const ContactManifold& m = c.manifold;
    const int n = static_cast<int>(m.points.size());
    Eigen::MatrixXd j(n, 12);
    Eigen::VectorXd u;
    Eigen::MatrixXd w;
    twoBodies(c, u, w);
    for (int i = 0; i < n; ++i) {
        const Vec3& p = m.points[static_cast<std::size_t>(i)];
        j.block<1, 3>(i, 0) = -m.normal.transpose();
        j.block<1, 3>(i, 3) = -(p - c.bodies[0].com).cross(m.normal).transpose();
        j.block<1, 3>(i, 6) = m.normal.transpose();
        j.block<1, 3>(i, 9) = (p - c.bodies[1].com).cross(m.normal).transpose();
    }
    const Eigen::MatrixXd k = j * w * j.transpose();
    const Eigen::VectorXd rhs = -(j * u);
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(k, Eigen::ComputeFullU | Eigen::ComputeFullV);
    svd.setThreshold(1e-10);
    return svd.solve(rhs);
}

ContactSolverSettings oneSweep() {
    ContactSolverSettings s;
    s.iterations = 1;
    s.shock_iterations = 0;
    s.warm_start = false;
    s.correction_iterations = 0;
    return s;
}

void expectBlockSolve(int count, bool collinear, bool a_static, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    int checked = 0;
    for (int trial = 0; trial < 200; ++trial) {
        Case c = randomPatch(rng, count, collinear, a_static);
        const Eigen::VectorXd expected = referenceImpulses(c);
        // With a negative entry the block step is refused and points relax one by one: another test.
        if (expected.minCoeff() < 0.0) continue;
        std::vector<ContactManifold> manifolds{c.manifold};
        std::vector<BodyImpulse> impulses;
        solveContactPhase(c.bodies, manifolds, 1.0 / 60.0, Vec3::Zero(), oneSweep(), impulses);
        ASSERT_EQ(manifolds[0].point_impulse.size(), static_cast<std::size_t>(count));
        for (int i = 0; i < count; ++i)
            EXPECT_NEAR(manifolds[0].point_impulse[static_cast<std::size_t>(i)], expected(i),
                        1e-9 * (1.0 + expected.cwiseAbs().maxCoeff()))
                << "seed " << seed << " trial " << trial << " point " << i;
        ++checked;
    }
    EXPECT_GE(checked, 40) << "too few patches with non-negative impulses to test";
}

TEST(ContactSolverBlock, FourPointPatchGetsTheMinimumNormImpulses) { expectBlockSolve(4, false, false, 11); }
TEST(ContactSolverBlock, ThreePointPatchGetsTheExactImpulses) { expectBlockSolve(3, false, false, 12); }
TEST(ContactSolverBlock, PatchOnAStaticBody) { expectBlockSolve(4, false, true, 13); }
TEST(ContactSolverBlock, CollinearPointsFallBackToTheGeneralInverse) { expectBlockSolve(4, true, false, 14); }
TEST(ContactSolverBlock, TwoPointPatch) { expectBlockSolve(2, false, false, 15); }


// A patch that sticks, alone on its two bodies, is solved whole: its normal points, the friction at
// its centroid and the spin friction about its normal in one solve, with no sweep after it. The
// reference: the minimum-norm solution of the explicitly assembled 12-dof system whose rows are the
// points' normals, the two tangents at the centroid and the spin about the normal (J W J^T, by SVD),
// which stops every point's approach and the pair's sliding and spin there.
struct Sticking {
    Eigen::VectorXd normal;   // per point
    Vec3 tangent;             // world
    double torsion = 0.0;
};

Sticking referenceSticking(const Case& c) {
    const ContactManifold& m = c.manifold;
    const int n = static_cast<int>(m.points.size());
    const Vec3 t1 = m.normal.unitOrthogonal(), t2 = m.normal.cross(t1);
    Eigen::MatrixXd j = Eigen::MatrixXd::Zero(n + 3, 12);
    Eigen::VectorXd u;
    Eigen::MatrixXd w;
    twoBodies(c, u, w);
    auto along = [&](int row, const Vec3& p, const Vec3& d) {
        j.block<1, 3>(row, 0) = -d.transpose();
        j.block<1, 3>(row, 3) = -(p - c.bodies[0].com).cross(d).transpose();
        j.block<1, 3>(row, 6) = d.transpose();
        j.block<1, 3>(row, 9) = (p - c.bodies[1].com).cross(d).transpose();
    };
    for (int i = 0; i < n; ++i) along(i, m.points[static_cast<std::size_t>(i)], m.normal);
    along(n, m.centroid, t1);
    along(n + 1, m.centroid, t2);
    j.block<1, 3>(n + 2, 3) = -m.normal.transpose();
    j.block<1, 3>(n + 2, 9) = m.normal.transpose();
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(j * w * j.transpose(), Eigen::ComputeFullU | Eigen::ComputeFullV);
    svd.setThreshold(1e-10);
    const Eigen::VectorXd x = svd.solve(-(j * u));
    return {x.head(n), x(n) * t1 + x(n + 1) * t2, x(n + 2)};
}

// The model's spin friction radius: (2/3) of the points' mean distance from the centroid.
double torsionRadius(const ContactManifold& m) {
    double mean = 0.0;
    for (const Vec3& p : m.points) mean += (p - m.centroid).norm();
    return (2.0 / 3.0) * mean / static_cast<double>(m.points.size());
}

ContactSolverSettings noPositionPass() {
    ContactSolverSettings s;
    s.warm_start = false;
    s.correction_iterations = 0;
    return s;
}

void expectWholeSolve(int count, bool a_static, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    int checked = 0;
    for (int trial = 0; trial < 400; ++trial) {
        Case c = randomPatch(rng, count, false, a_static);
        c.manifold.friction = 2.0;
        const Sticking expected = referenceSticking(c);
        const double sum = expected.normal.sum(), limit = c.manifold.friction * sum;
        // Only patches whose sticking answer pushes at every point and lies inside both cones
        // (with a margin, so rounding cannot tip one over).
        if (expected.normal.minCoeff() < 0.0 || expected.tangent.norm() > 0.99 * limit ||
            std::abs(expected.torsion) > 0.99 * limit * torsionRadius(c.manifold))
            continue;
        std::vector<ContactManifold> manifolds{c.manifold};
        std::vector<BodyImpulse> impulses;
        const ContactSolverReport report =
            solveContactPhase(c.bodies, manifolds, 1.0 / 60.0, Vec3::Zero(), noPositionPass(), impulses);
        EXPECT_EQ(report.sweeps, 1) << "seed " << seed << " trial " << trial;
        EXPECT_EQ(report.shock_sweeps, 0) << "seed " << seed << " trial " << trial;
        const double scale = 1e-9 * (1.0 + expected.normal.cwiseAbs().maxCoeff());
        ASSERT_EQ(manifolds[0].point_impulse.size(), static_cast<std::size_t>(count));
        for (int i = 0; i < count; ++i)
            EXPECT_NEAR(manifolds[0].point_impulse[static_cast<std::size_t>(i)], expected.normal(i), scale)
                << "seed " << seed << " trial " << trial << " point " << i;
        EXPECT_LE((manifolds[0].tangent_impulse - expected.tangent).norm(), scale) << "seed " << seed << " trial " << trial;
        EXPECT_NEAR(manifolds[0].torsion_impulse, expected.torsion, scale) << "seed " << seed << " trial " << trial;
        ++checked;
    }
    EXPECT_GE(checked, 40) << "too few sticking patches to test";
}

TEST(ContactSolverWholePatch, FourPointStickingPatchIsSolvedWholeInOneSweep) { expectWholeSolve(4, false, 21); }
TEST(ContactSolverWholePatch, ThreePointStickingPatchIsSolvedWholeInOneSweep) { expectWholeSolve(3, false, 22); }
TEST(ContactSolverWholePatch, StickingPatchOnAStaticBody) { expectWholeSolve(4, true, 23); }

// A patch whose sticking answer lies outside the friction cone is not solved whole: it is relaxed
// part by part, and its friction ends on the cone (|friction| = mu x the sum of its normal impulses).
TEST(ContactSolverWholePatch, SlidingPatchKeepsItsFrictionOnTheCone) {
    std::mt19937_64 rng(24);
    int checked = 0;
    for (int trial = 0; trial < 400; ++trial) {
        Case c = randomPatch(rng, 4, false, true);
        // A tangential slide on top of the approach.
        const Vec3 t = c.manifold.normal.unitOrthogonal();
        c.bodies[1].velocity += 0.5 * t;
        c.manifold.friction = 0.1;
        const Sticking stuck = referenceSticking(c);
        if (stuck.normal.minCoeff() < 0.0 || !(stuck.tangent.norm() > 1.5 * 0.1 * stuck.normal.sum())) continue;
        std::vector<ContactManifold> manifolds{c.manifold};
        std::vector<BodyImpulse> impulses;
        const ContactSolverReport report =
            solveContactPhase(c.bodies, manifolds, 1.0 / 60.0, Vec3::Zero(), noPositionPass(), impulses);
        EXPECT_GT(report.sweeps, 1) << "trial " << trial;
        double sum = 0.0;
        for (double x : manifolds[0].point_impulse) sum += x;
        EXPECT_NEAR(manifolds[0].tangent_impulse.norm(), 0.1 * sum, 1e-9 * (1.0 + sum)) << "trial " << trial;
        ++checked;
    }
    EXPECT_GE(checked, 40) << "too few sliding patches to test";
}

// The cold solve's extra sweeps (ContactSolverSettings::cold_factor) are for an island whose
// touching patches have no impulses to start from. A grid of boxes resting on a floor, each patch
// warm from the last solve, with speculative patches between neighbours (beyond the collision
// distance, so their last impulse was zero): counted as cold, those made most of the island's
// patches "cold" (31 of 51) and every such solve ran 24x the sweeps.
struct Grid {
    std::vector<RigidBody> bodies;
    std::vector<ContactManifold> manifolds;
};

Grid restingGrid(bool warm) {
    constexpr int kRows = 4, kColumns = 5;
    constexpr double kGap = 0.005;   // [m] between neighbours: speculative for cd = 1 mm
    Grid grid;
    Body floor;
    floor.name = "floor";
    floor.role = BodyRole::Real;
    floor.shape = Shape::box(Vec3(20.0, 20.0, 0.5));
    floor.pose = at(Vec3(0.0, 0.0, -0.5));
    grid.bodies.push_back(RigidBody::fromScene(floor));
    auto index = [](int r, int c) { return 1 + r * kColumns + c; };
    for (int r = 0; r < kRows; ++r)
        for (int c = 0; c < kColumns; ++c) {
            Body b;
            b.name = "box";
            b.role = BodyRole::Virtual;
            b.shape = Shape::box(Vec3(0.1, 0.1, 0.1));
            b.mass_properties = massProperties(b.shape, 1.0);
            b.pose = at(Vec3((0.2 + kGap) * c, (0.2 + kGap) * r, 0.1));
            grid.bodies.push_back(RigidBody::fromScene(b));
        }
    const double h = 1.0 / 60.0, load = 9.81 * h / 4.0;   // [N s] a quarter of m g h per corner
    auto manifold = [](int a, int b, const Vec3& n, const Vec3& centre, double gap) {
        ContactManifold m;
        m.body_a = a;
        m.body_b = b;
        m.normal = n;
        m.distance = gap;
        m.friction = 0.5;
        const Vec3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
        for (const double s : {-1.0, 1.0})
            for (const double q : {-1.0, 1.0}) {
                m.points.push_back(centre + 0.09 * s * t1 + 0.09 * q * t2);
                m.point_gap.push_back(gap);
            }
        m.centroid = centre;
        m.point_impulse.assign(4, 0.0);   // solved last time, nothing pressed on it
        return m;
    };
    for (int k = 1; k <= kRows * kColumns; ++k) {
        const Vec3 base = grid.bodies[static_cast<std::size_t>(k)].com - Vec3(0.0, 0.0, 0.1);
        ContactManifold m = manifold(0, k, Vec3::UnitZ(), base, 0.0005);
        m.point_impulse.assign(4, warm ? load : 0.0);
        grid.manifolds.push_back(m);
    }
    for (int r = 0; r < kRows; ++r)
        for (int c = 0; c < kColumns; ++c) {
            const Vec3 com = grid.bodies[static_cast<std::size_t>(index(r, c))].com;
            if (c + 1 < kColumns)
                grid.manifolds.push_back(manifold(index(r, c), index(r, c + 1), Vec3::UnitX(), com + Vec3(0.1, 0.0, 0.0), kGap));
            if (r + 1 < kRows)
                grid.manifolds.push_back(manifold(index(r, c), index(r + 1, c), Vec3::UnitY(), com + Vec3(0.0, 0.1, 0.0), kGap));
        }
    return grid;
}

int sweepsOfGrid(bool warm) {
    Grid grid = restingGrid(warm);
    ContactSolverSettings s;
    s.speculative_from = 0.001;   // the collision distance of the fixed-tick regimes
    s.speculative_target = 0.0005;
    s.tolerance = 0.0;            // every sweep runs: the count is the schedule's
    std::vector<BodyImpulse> impulses;
    return solveContactPhase(grid.bodies, grid.manifolds, 1.0 / 60.0, Vec3(0.0, 0.0, -9.81), s, impulses).sweeps;
}

TEST(ContactSolverSweeps, SpeculativePatchesDoNotMakeAWarmIslandCold) {
    const ContactSolverSettings defaults;
    EXPECT_EQ(sweepsOfGrid(true), defaults.iterations);
    // The rule still gives a pile's first solve its extra sweeps.
    EXPECT_EQ(sweepsOfGrid(false), defaults.cold_factor * defaults.iterations);
}

// The position pass freezes the body nearer the ground (shock propagation). In a pile, a body may
// reach the ground by a shorter path than the body below it: box B lies across box A (20 mm into
// it) and a static ledge, so B is one contact from a static body and A, on box C on the floor, two.
// Frozen as "lower", B made A's push drive A down into C, which pushed A back up: the two cancelled
// and the pair was never separated (a 400-box bin: one pair sank from 2 mm to 91 mm over two
// seconds, 52 emergency repairs). A body lying above its lower-level neighbour along the patch
// normal is not frozen: B is lifted out of A, A stays on C. The ruler: the rate of the pass,
// correction_rate x (target - gap), of which B must get most (A, held by C, almost none).
Vec3 positionPassLift(int body, std::vector<BodyImpulse>* all = nullptr) {
    const double cd = 0.001, depth = 0.02;
    auto staticBox = [](const Vec3& half, const Vec3& centre) {
        Body b;
        b.role = BodyRole::Real;
        b.shape = Shape::box(half);
        b.pose = at(centre);
        return RigidBody::fromScene(b);
    };
    auto box = [](const Vec3& half, const Vec3& centre) {
        Body b;
        b.role = BodyRole::Virtual;
        b.shape = Shape::box(half);
        b.mass_properties = massProperties(b.shape, 1.0);
        b.pose = at(centre);
        return RigidBody::fromScene(b);
    };
    // 0 floor, 1 ledge (top at z = 0.38), 2 C, 3 A (top at z = 0.4), 4 B (bottom at z = 0.38).
    std::vector<RigidBody> bodies = {staticBox(Vec3(2.0, 2.0, 0.5), Vec3(0.0, 0.0, -0.5)),
                                     staticBox(Vec3(0.1, 0.1, 0.19), Vec3(0.3, 0.0, 0.19)),
                                     box(Vec3(0.1, 0.1, 0.1), Vec3(0.0, 0.0, 0.1)),
                                     box(Vec3(0.1, 0.1, 0.1), Vec3(0.0, 0.0, 0.3)),
                                     box(Vec3(0.25, 0.1, 0.1), Vec3(0.15, 0.0, 0.4 - depth + 0.1))};
    auto patch = [](int a, int b, const Vec3& centre, double half_x, double gap) {
        ContactManifold m;
        m.body_a = a;
        m.body_b = b;
        m.normal = Vec3::UnitZ();
        m.distance = gap;
        m.friction = 0.5;
        for (const double sx : {-1.0, 1.0})
            for (const double sy : {-1.0, 1.0}) {
                m.points.push_back(centre + Vec3(sx * half_x, sy * 0.09, 0.0));
                m.point_gap.push_back(gap);
            }
        m.centroid = centre;
        return m;
    };
    std::vector<ContactManifold> manifolds = {patch(0, 2, Vec3(0.0, 0.0, 0.0), 0.09, 0.25 * cd),
                                              patch(2, 3, Vec3(0.0, 0.0, 0.2), 0.09, 0.25 * cd),
                                              patch(1, 4, Vec3(0.3, 0.0, 0.38), 0.09, 0.25 * cd),
                                              patch(3, 4, Vec3(0.0, 0.0, 0.39), 0.09, -depth)};
    ContactSolverSettings s;
    s.correction_floor = -0.01 * cd;   // the native backend's (island_step.cpp)
    s.correction_target = 0.25 * cd;
    std::vector<BodyImpulse> impulses;
    solveContactPhase(bodies, manifolds, 1.0 / 60.0, Vec3(0.0, 0.0, -9.81), s, impulses);
    if (all) *all = impulses;
    return impulses[static_cast<std::size_t>(body)].displacement;
}

TEST(ContactSolverPositionPass, ABodyAboveItsLowerLevelNeighbourIsLiftedNotPushedDown) {
    const ContactSolverSettings defaults;
    const double wanted = defaults.correction_rate * (0.25e-3 + 0.02);   // [m] the pass's step for the A-B patch
    const Vec3 b = positionPassLift(4), a = positionPassLift(3);
    EXPECT_GT(b.z(), 0.75 * wanted) << "B is not lifted out of A";
    EXPECT_GT(a.z(), -0.1 * wanted) << "A is pushed down into C";
    EXPECT_GT(b.z() - a.z(), 0.9 * wanted);
}

// End targets (fixed ticks): whichever way a body moves over the step, at the mean of its start and
// end velocities (a drift) or at its end velocity from the start (a contact the tick turns into an
// impact), no point of a patch closes by more than it may: a touching point (gap below the
// collision distance) not at all, a speculative one to the speculative target. Checked by the
// kinematics of each point that does not approach at the start (an approach is the collision
// phase's) against the solve's end velocities, for random patches of touching and speculative
// points on random bodies, parting or closing slowly. Without end targets a parting point may slow
// down to minus its start speed: its end velocity then closes it (the check fails for some patch).
int endTargetViolations(bool end_targets, std::uint64_t seed) {
    const double cd = 1e-3, h = 1.0 / 60.0;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int violations = 0;
    for (int trial = 0; trial < 300; ++trial) {
        Case c = randomPatch(rng, 4, false, trial % 2 == 0);
        ContactManifold& m = c.manifold;
        m.friction = 0.3 * std::abs(u(rng));
        for (std::size_t i = 0; i < m.points.size(); ++i)
            m.point_gap.push_back(i % 2 == 0 ? cd * std::abs(u(rng)) : cd * (1.0 + 4.0 * std::abs(u(rng))));
        m.distance = *std::min_element(m.point_gap.begin(), m.point_gap.end());
        // B parting from A or closing slowly along the normal, with some spin.
        c.bodies[1].velocity = c.bodies[0].velocity + (0.3 * u(rng) + 0.1) * m.normal;
        ContactSolverSettings s = noPositionPass();
        s.iterations = 40;
        s.speculative_from = cd;
        s.speculative_target = 0.5 * cd;
        s.end_targets = end_targets;
        std::vector<RigidBody> bodies = c.bodies;
        std::vector<ContactManifold> manifolds{m};
        std::vector<BodyImpulse> impulses;
        solveContactPhase(bodies, manifolds, h, Vec3::Zero(), s, impulses);
        std::vector<RigidBody> end = bodies;
        for (std::size_t k = 0; k < end.size(); ++k) {
            if (end[k].infiniteMass()) continue;
            end[k].velocity += end[k].inv_mass * impulses[k].linear;
            end[k].angular_momentum += impulses[k].angular;
            end[k].refreshEnergy();
        }
        for (std::size_t i = 0; i < m.points.size(); ++i) {
            const Vec3& p = m.points[i];
            const double start = -approachAt(bodies[0], bodies[0].angularVelocity(), bodies[1], bodies[1].angularVelocity(), p, m.normal);
            const double finish = -approachAt(end[0], end[0].angularVelocity(), end[1], end[1].angularVelocity(), p, m.normal);
            const double gap = m.point_gap[i];
            const double allowed = gap < cd ? 0.0 : gap - 0.5 * cd;   // how far the point may close
            const double slack = 1e-9 + 1e-7 * h;
            // A point approaching at the start is the collision phase's (it meets it first).
            if (start >= 0.0) {
                EXPECT_GE(h * 0.5 * (start + finish), -allowed - slack) << "seed " << seed << " trial " << trial << " point " << i;
            }
            if (start >= 0.0 && h * finish < -allowed - slack) ++violations;
        }
    }
    return violations;
}

TEST(ContactSolverEndTargets, EveryPointHoldsAtItsEndVelocityToo) {
    EXPECT_EQ(endTargetViolations(true, 31), 0);
    EXPECT_EQ(endTargetViolations(true, 32), 0);
    // The check can fail: without end targets, parting points are let close at their end speed.
    EXPECT_GT(endTargetViolations(false, 31), 0);
}

}  // namespace
}  // namespace vroc::native::test
