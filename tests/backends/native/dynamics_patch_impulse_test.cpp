// SPDX-License-Identifier: MIT
// The patch impulse (dynamics/patch_impulse.h) against closed forms and a brute-force
// complementarity solve: a flat box landing on four corners leaves at e times its speed without
// turning; a rocking plate's approaching corner is stopped and nothing is pulled; random
// frictionless patches match the active-set enumeration of the same small LCP; sticking patches
// match the enumeration of the same problem with the centroid's friction free, and stop its slip.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/LU>

#include "dynamics/newton_coulomb.h"
#include "dynamics/patch_impulse.h"
#include "lcp_enumeration.h"
#include "native_test_scenes.h"

namespace vroc::native::test {
namespace {

RigidBody boxBody(const Vec3& half, double mass, const Pose& pose, const Vec3& v, const Vec3& w) {
    Body b;
    b.name = "box";
    b.role = BodyRole::Virtual;
    b.shape = Shape::box(half);
    b.mass_properties = massProperties(b.shape, mass);
    b.pose = pose;
    b.linear_velocity = v;
    b.angular_velocity = w;
    return RigidBody::fromScene(b);
}

RigidBody ground() {
    Body b;
    b.name = "floor";
    b.role = BodyRole::Real;
    b.shape = Shape::box(Vec3(10, 10, 1));
    b.pose = at(Vec3(0, 0, -1));
    return RigidBody::fromScene(b);
}

// The four bottom corners of an axis-aligned box at the origin with half extents h (z = -h.z).
std::vector<Vec3> bottomCorners(const Vec3& h) {
    return {Vec3(-h.x(), -h.y(), -h.z()), Vec3(h.x(), -h.y(), -h.z()), Vec3(h.x(), h.y(), -h.z()),
            Vec3(-h.x(), h.y(), -h.z())};
}

double normalSpeed(const RigidBody& a, const RigidBody& b, const Vec3& p, const Vec3& n) {
    return (b.pointVelocity(p) - a.pointVelocity(p)).dot(n);
}

TEST(DynamicsPatchImpulse, FlatBoxLeavesAtRestitutionTimesItsSpeedWithoutTurning) {
    const Vec3 h(0.3, 0.2, 0.1);
    for (double e : {0.0, 0.5, 1.0}) {
        RigidBody floor = ground();
        RigidBody box = boxBody(h, 2.0, at(Vec3::Zero()), Vec3(0, 0, -3.0), Vec3::Zero());
        const std::vector<Vec3> pts = bottomCorners(h);
        const PatchImpulse imp = patchImpulse(floor, box, pts, Vec3(0, 0, -h.z()), Vec3::UnitZ(),
                                              std::vector<double>(4, e), 0.5);
        applyPatchImpulse(floor, box, pts, Vec3::UnitZ(), imp);
        EXPECT_NEAR(box.velocity.z(), 3.0 * e, 1e-12) << "e = " << e;
        EXPECT_NEAR(box.velocity.head<2>().norm(), 0.0, 1e-12) << "e = " << e;
        EXPECT_LT(box.angularVelocity().norm(), 1e-12) << "e = " << e;
        double total = 0.0;
        for (double x : imp.normal) total += x;
        EXPECT_NEAR(total, 2.0 * 3.0 * (1.0 + e), 1e-12) << "m (1 + e) v, e = " << e;
    }
}

TEST(DynamicsPatchImpulse, RockingPlateIsStoppedAtTheApproachingCornerAndNothingIsPulled) {
    // A thin plate turning about its long axis: one long edge approaches the floor, the other rises;
    // its centroid is still, so a centroid impulse does nothing. Plastic (e = 0), with friction.
    const Vec3 h(0.3, 0.2, 0.01);
    RigidBody floor = ground();
    RigidBody plate = boxBody(h, 0.5, at(Vec3::Zero()), Vec3::Zero(), Vec3(2.0, 0.0, 0.0));
    const std::vector<Vec3> pts = bottomCorners(h);
    for (const Vec3& p : pts) ASSERT_NE(normalSpeed(floor, plate, p, Vec3::UnitZ()), 0.0);
    const PatchImpulse imp = patchImpulse(floor, plate, pts, Vec3(0, 0, -h.z()), Vec3::UnitZ(),
                                          std::vector<double>(4, 0.0), 0.6);
    applyPatchImpulse(floor, plate, pts, Vec3::UnitZ(), imp);
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const double u = normalSpeed(floor, plate, pts[i], Vec3::UnitZ());
        EXPECT_GE(imp.normal[i], 0.0) << "point " << i << " pulled";
        EXPECT_GE(u, -1e-9) << "point " << i << " still approaches";
        if (imp.normal[i] > 1e-12) {
            EXPECT_NEAR(u, 0.0, 1e-9) << "a pushing point ends at its target, point " << i;
        }
    }
    // The rotation about the approaching edge stops: every corner ends at or above zero normal speed
    // and the plate no longer turns into the floor.
    EXPECT_LT(plate.angularVelocity().x(), 2.0);
}

// A box of random size and mass landing on a large box below it with 2-4 of its bottom corners:
// the lower box moves at up to `va` m/s and turns at up to `wa` rad/s per axis, the upper one falls
// at 0.5-1.5 m/s and turns at up to `wb`.
struct Landing {
    RigidBody a, b;
    Vec3 h;
    std::vector<Vec3> pts;
};

Landing randomLanding(std::mt19937_64& rng, double va, double wa, double wb) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Landing l;
    l.h = Vec3(0.1 + 0.3 * std::abs(u(rng)), 0.1 + 0.3 * std::abs(u(rng)), 0.05 + 0.2 * std::abs(u(rng)));
    l.a = boxBody(Vec3(1, 1, 1), 3.0, at(Vec3(0, 0, -1.0 - l.h.z())), Vec3(u(rng), u(rng), u(rng)) * va,
                  Vec3(u(rng), u(rng), u(rng)) * wa);
    l.b = boxBody(l.h, 1.0 + std::abs(u(rng)), at(Vec3::Zero()), Vec3(u(rng), u(rng), -1.0 + 0.5 * u(rng)),
                  Vec3(u(rng), u(rng), u(rng)) * wb);
    const int count = 2 + static_cast<int>(3 * std::abs(u(rng))) % 3;   // 2..4 corners
    l.pts = bottomCorners(l.h);
    l.pts.resize(static_cast<std::size_t>(count));
    return l;
}

TEST(DynamicsPatchImpulse, FrictionlessPatchesMatchTheEnumeratedComplementaritySolution) {
    std::mt19937_64 rng(2201);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int checked = 0;
    for (int trial = 0; trial < 200; ++trial) {
        auto [a, b, h, pts] = randomLanding(rng, 0.5, 1.0, 3.0);
        const int count = static_cast<int>(pts.size());
        std::vector<double> e(pts.size());
        for (double& x : e) x = std::abs(u(rng));
        const Vec3 n = Vec3::UnitZ();
        // The LCP of the same impact, assembled independently from the bodies' collision matrices.
        Eigen::MatrixXd m(count, count);
        Eigen::VectorXd q(count);
        for (int i = 0; i < count; ++i) {
            const double u0 = normalSpeed(a, b, pts[static_cast<std::size_t>(i)], n);
            q(i) = u0 - (u0 < 0.0 ? -e[static_cast<std::size_t>(i)] * u0 : 0.0);
            for (int j = 0; j < count; ++j) {
                // Relative normal velocity change at i per unit normal impulse at j (on B, -on A).
                RigidBody a2 = a, b2 = b;
                a2.applyImpulse(-n, pts[static_cast<std::size_t>(j)]);
                b2.applyImpulse(n, pts[static_cast<std::size_t>(j)]);
                m(i, j) = normalSpeed(a2, b2, pts[static_cast<std::size_t>(i)], n) - u0;
            }
        }
        bool any_approach = false;
        for (int i = 0; i < count; ++i) any_approach = any_approach || normalSpeed(a, b, pts[static_cast<std::size_t>(i)], n) < 0.0;
        if (!any_approach) continue;
        const Eigen::VectorXd expect = enumerateLcp(m, q);
        ASSERT_GT(expect.size(), 0) << "trial " << trial << ": no LCP solution found";
        const PatchImpulse imp = patchImpulse(a, b, pts, Vec3(0, 0, -h.z()), n, e, 0.0);
        // Compare the resulting normal velocities (unique even where the impulses are not).
        const Eigen::VectorXd w_expect = m * expect + q;
        Eigen::VectorXd got(count);
        for (int i = 0; i < count; ++i) got(i) = imp.normal[static_cast<std::size_t>(i)];
        const Eigen::VectorXd w_got = m * got + q;
        for (int i = 0; i < count; ++i)
            EXPECT_NEAR(w_got(i), w_expect(i), 1e-6 * (1.0 + q.cwiseAbs().maxCoeff()))
                << "trial " << trial << ", point " << i << " of " << count;
        ++checked;
    }
    EXPECT_GT(checked, 100);
}

// The sticking patch impact by brute force: every set of pushing points, with the centroid's two
// friction impulses free, solved as one linear system of the collision matrix probed impulse by
// impulse; the answer is the set whose impulses push, whose other points do not approach and whose
// centroid stops slipping.
struct StickingAnswer {
    bool found = false;
    Eigen::VectorXd normal;    // per point
    Eigen::Vector2d friction;  // along t1, t2
};

StickingAnswer enumerateSticking(const Eigen::MatrixXd& full, const Eigen::VectorXd& q, int count) {
    StickingAnswer best;
    double best_norm = std::numeric_limits<double>::infinity();
    for (int mask = 0; mask < (1 << count); ++mask) {
        std::vector<int> rows;
        for (int i = 0; i < count; ++i)
            if (mask >> i & 1) rows.push_back(i);
        rows.push_back(count);
        rows.push_back(count + 1);
        const Eigen::VectorXd x = solveOnRows(full, q, rows);
        const Eigen::VectorXd w = full * x + q;
        bool ok = std::abs(w(count)) < 1e-9 && std::abs(w(count + 1)) < 1e-9;
        for (int i = 0; i < count; ++i) ok = ok && x(i) >= -1e-9 && w(i) >= -1e-9 && std::abs(x(i) * w(i)) < 1e-9;
        if (ok && x.head(count).norm() < best_norm) {
            best_norm = x.head(count).norm();
            best.found = true;
            best.normal = x.head(count);
            best.friction = x.tail(2);
        }
    }
    return best;
}

// A patch's rows, measured on the bodies (RigidBody::applyImpulse): each point's normal speed, then
// the centroid's slip along t1 and t2; the columns of `full`, the change of those speeds per unit
// normal impulse at each point, then per unit friction impulse at the centroid along t1 and t2; q,
// the speeds less the targets (an approaching point must leave at e times its approach speed).
struct PatchRows {
    Vec3 c, t1, t2;
    Eigen::VectorXd u0, q;
    Eigen::MatrixXd full;
    bool approaching = false;   // some point approaches: an impact
};

PatchRows patchRows(const RigidBody& a, const RigidBody& b, const std::vector<Vec3>& pts, const Vec3& n,
                    const std::vector<double>& e) {
    const int count = static_cast<int>(pts.size());
    PatchRows r;
    r.c = Vec3::Zero();
    for (const Vec3& p : pts) r.c += p;
    r.c /= static_cast<double>(count);
    const Vec3& c = r.c;
    r.t1 = n.unitOrthogonal();
    r.t2 = n.cross(r.t1);
    auto speeds = [&](const RigidBody& ra, const RigidBody& rb) {
        Eigen::VectorXd v(count + 2);
        for (int i = 0; i < count; ++i) v(i) = normalSpeed(ra, rb, pts[static_cast<std::size_t>(i)], n);
        const Vec3 slip = rb.pointVelocity(c) - ra.pointVelocity(c);
        v(count) = slip.dot(r.t1);
        v(count + 1) = slip.dot(r.t2);
        return v;
    };
    r.u0 = speeds(a, b);
    r.full.resize(count + 2, count + 2);
    for (int j = 0; j < count + 2; ++j) {
        const Vec3 dir = j < count ? n : (j == count ? r.t1 : r.t2);
        const Vec3 at_point = j < count ? pts[static_cast<std::size_t>(j)] : c;
        RigidBody a2 = a, b2 = b;
        a2.applyImpulse(-dir, at_point);
        b2.applyImpulse(dir, at_point);
        r.full.col(j) = speeds(a2, b2) - r.u0;
    }
    r.q = r.u0;
    for (int i = 0; i < count; ++i) {
        r.approaching = r.approaching || r.u0(i) < 0.0;
        r.q(i) -= r.u0(i) < 0.0 ? -e[static_cast<std::size_t>(i)] * r.u0(i) : 0.0;
    }
    return r;
}

TEST(DynamicsPatchImpulse, StickingPatchesStopTheCentroidAndMatchTheEnumeratedSolution) {
    std::mt19937_64 rng(2202);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int sticking = 0, sliding = 0;
    for (int trial = 0; trial < 300; ++trial) {
        auto [a, b, h, pts] = randomLanding(rng, 0.2, 0.3, 2.0);
        const int count = static_cast<int>(pts.size());
        std::vector<double> e(pts.size());
        for (double& x : e) x = 0.5 * std::abs(u(rng));
        const double mu = 0.3 + 2.0 * std::abs(u(rng));
        const Vec3 n = Vec3::UnitZ();
        const PatchRows rows = patchRows(a, b, pts, n, e);
        if (!rows.approaching) continue;
        const Vec3 &c = rows.c, &t1 = rows.t1, &t2 = rows.t2;
        const Eigen::MatrixXd& full = rows.full;
        const Eigen::VectorXd& q = rows.q;
        const StickingAnswer expect = enumerateSticking(full, q, count);
        const PatchImpulse imp = patchImpulse(a, b, pts, c, n, e, mu);
        if (!expect.found || expect.friction.norm() > mu * expect.normal.sum() * (1.0 - 1e-9)) {
            // Sliding: the friction impulse lies on the cone, never beyond it.
            double sum = 0.0;
            for (double x : imp.normal) sum += x;
            EXPECT_LE(imp.tangent.norm(), mu * sum * (1.0 + 1e-9) + 1e-12) << "trial " << trial;
            ++sliding;
            continue;
        }
        // Sticking: the same speeds after the impact, and the centroid stopped.
        Eigen::VectorXd got(count + 2);
        for (int i = 0; i < count; ++i) got(i) = imp.normal[static_cast<std::size_t>(i)];
        got(count) = imp.tangent.dot(t1);
        got(count + 1) = imp.tangent.dot(t2);
        Eigen::VectorXd want(count + 2);
        want << expect.normal, expect.friction;
        const Eigen::VectorXd w_got = full * got + q, w_want = full * want + q;
        const double scale = 1.0 + q.cwiseAbs().maxCoeff();
        for (int i = 0; i < count + 2; ++i) EXPECT_NEAR(w_got(i), w_want(i), 1e-9 * scale) << "trial " << trial << ", row " << i;
        EXPECT_NEAR(w_got(count), 0.0, 1e-9 * scale) << "trial " << trial;
        EXPECT_NEAR(w_got(count + 1), 0.0, 1e-9 * scale) << "trial " << trial;
        ++sticking;
    }
    EXPECT_GT(sticking, 50);
    EXPECT_GT(sliding, 10);
}

// A sliding patch, measured on the bodies (RigidBody::applyImpulse), not on the impulse's own
// matrices: its friction acts at the normal impulses' centre of pressure, lies on the cone, and is
// the stopping friction there (the slip of the bodies with the normal impulses alone, stopped by
// the tangential mass at that point, probed impulse by impulse) brought onto the cone; the normal
// impulses, with that friction, push no point below its target and every pushing point to it. The
// friction at the centroid (before) fails the first check on every sliding patch (303 of 303 here).
TEST(DynamicsPatchImpulse, SlidingPatchesMeetTheFixedPointWithFrictionAtTheCentreOfPressure) {
    std::mt19937_64 rng(2203);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int sliding = 0, at_fixed_point = 0;
    for (int trial = 0; trial < 400; ++trial) {
        auto [a, b, h, pts] = randomLanding(rng, 1.5, 1.0, 3.0);
        const int count = static_cast<int>(pts.size());
        std::vector<double> e(pts.size());
        for (double& x : e) x = 0.5 * std::abs(u(rng));
        const double mu = 0.1 + 0.4 * std::abs(u(rng));
        const Vec3 n = Vec3::UnitZ();
        const PatchRows rows = patchRows(a, b, pts, n, e);
        if (!rows.approaching) continue;
        const PatchImpulse imp = patchImpulse(a, b, pts, rows.c, n, e, mu);
        double sum = 0.0;
        Vec3 weighted = Vec3::Zero();
        for (int i = 0; i < count; ++i) {
            ASSERT_GE(imp.normal[static_cast<std::size_t>(i)], 0.0) << "trial " << trial << ": point " << i << " pulled";
            sum += imp.normal[static_cast<std::size_t>(i)];
            weighted += imp.normal[static_cast<std::size_t>(i)] * pts[static_cast<std::size_t>(i)];
        }
        ASSERT_TRUE(sum > 0.0) << "trial " << trial;
        if (imp.tangent.norm() < mu * sum * (1.0 - 1e-9)) continue;   // sticking: the test above
        ++sliding;
        const Vec3 cp = weighted / sum;
        EXPECT_LT((imp.tangent_point - cp).norm(), 1e-9 * h.norm()) << "trial " << trial << ": friction not at the centre of pressure";
        EXPECT_NEAR(imp.tangent.norm(), mu * sum, 1e-9 * mu * sum) << "trial " << trial << ": friction off the cone";
        // The stopping friction at cp given the normal impulses, from the bodies.
        RigidBody an = a, bn = b;
        for (int i = 0; i < count; ++i) {
            an.applyImpulse(-imp.normal[static_cast<std::size_t>(i)] * n, pts[static_cast<std::size_t>(i)]);
            bn.applyImpulse(imp.normal[static_cast<std::size_t>(i)] * n, pts[static_cast<std::size_t>(i)]);
        }
        const Vec3 slip = bn.pointVelocity(cp) - an.pointVelocity(cp);
        Eigen::Matrix2d k;
        for (int j = 0; j < 2; ++j) {
            const Vec3 dir = j == 0 ? rows.t1 : rows.t2;
            RigidBody a2 = an, b2 = bn;
            a2.applyImpulse(-dir, cp);
            b2.applyImpulse(dir, cp);
            const Vec3 d = (b2.pointVelocity(cp) - a2.pointVelocity(cp)) - slip;
            k(0, j) = d.dot(rows.t1);
            k(1, j) = d.dot(rows.t2);
        }
        Eigen::Vector2d stop = -k.inverse() * Eigen::Vector2d(slip.dot(rows.t1), slip.dot(rows.t2));
        stop *= mu * sum / stop.norm();
        const Vec3 expect = stop(0) * rows.t1 + stop(1) * rows.t2;
        // The normal speeds with both applied.
        RigidBody af = a, bf = b;
        applyPatchImpulse(af, bf, pts, n, imp);
        bool complementary = true;
        const double scale = 1.0 + rows.u0.head(count).cwiseAbs().maxCoeff();
        for (int i = 0; i < count; ++i) {
            const double target = rows.u0(i) - rows.q(i);
            const double w = normalSpeed(af, bf, pts[static_cast<std::size_t>(i)], n) - target;
            complementary = complementary && w >= -1e-5 * scale;
            if (imp.normal[static_cast<std::size_t>(i)] > 1e-9 * sum) complementary = complementary && std::abs(w) <= 1e-5 * scale;
        }
        if (complementary && (imp.tangent - expect).norm() <= 1e-5 * mu * sum) ++at_fixed_point;
    }
    EXPECT_GT(sliding, 100);
    // All 298 here; a patch may stop at the evaluation cap a little short of it.
    EXPECT_GE(at_fixed_point, 0.95 * sliding) << at_fixed_point << " of " << sliding;
}

TEST(DynamicsPatchImpulse, OnePointAgreesWithTheSinglePointModel) {
    std::mt19937_64 rng(7);
    for (int trial = 0; trial < 50; ++trial) {
        RigidBody a = randomBody(rng), b = randomBody(rng);
        const Vec3 p = 0.5 * (a.com + b.com);
        const Vec3 n = (b.com - a.com).normalized();
        if (!((b.pointVelocity(p) - a.pointVelocity(p)).dot(n) < 0.0)) continue;
        const ImpulseResult single = newtonCoulombImpulse(a, b, p, n, 0.4, 0.0);
        const PatchImpulse patch = patchImpulse(a, b, std::vector<Vec3>{p}, p, n, std::vector<double>{0.4}, 0.0);
        EXPECT_NEAR(patch.normal[0], single.impulse.dot(n), 1e-9 * (1.0 + std::abs(single.impulse.dot(n)))) << "trial " << trial;
    }
}

}  // namespace
}  // namespace vroc::native::test
