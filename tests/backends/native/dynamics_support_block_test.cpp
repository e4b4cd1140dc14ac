// SPDX-License-Identifier: MIT
// A body held by rows against bodies that do not move, solved at once (SupportBlock): against the
// explicitly assembled system. For random rows, masses and errors the velocity change must be the
// least-squares fit of W^T du = e (SVD of W^T) and the impulses the minimum-norm solution of
// (W^T M^-1 W) p = e (SVD); rows that leave a direction free are refused. Then in the contact phase:
// a box bridging two static blocks, solved by shock propagation alone, must come to rest in its
// first shock sweep (closed form), its rows' impulses the minimum-norm split (SVD).
#include <gtest/gtest.h>

#include <random>

#include <Eigen/SVD>

#include "dynamics/contact_solver.h"
#include "dynamics/support_block.h"
#include "native_test_scenes.h"

namespace vroc::native::test {
namespace {

struct RandomRows {
    std::vector<SupportRow> rows;
    double inv_mass = 0.0;
    Mat3 inv_inertia = Mat3::Zero();
};

// `patches` patches of four points, each with its two friction rows and its spin row, in random
// planes around the body; random mass and inertia.
RandomRows randomRows(std::mt19937_64& rng, int patches) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    RandomRows r;
    r.inv_mass = 1.0 / (0.5 + 2.0 * std::abs(u(rng)));
    const Mat3 q = Eigen::AngleAxisd(3.0 * u(rng), Vec3(u(rng), u(rng), u(rng)).normalized()).toRotationMatrix();
    const Vec3 moments(0.1 + std::abs(u(rng)), 0.1 + std::abs(u(rng)), 0.1 + std::abs(u(rng)));
    r.inv_inertia = q * moments.cwiseInverse().asDiagonal() * q.transpose();
    for (int k = 0; k < patches; ++k) {
        const Vec3 n = Vec3(u(rng), u(rng), u(rng)).normalized();
        const Vec3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
        const Vec3 centre = -0.5 * n + 0.2 * (u(rng) * t1 + u(rng) * t2);
        for (int i = 0; i < 4; ++i) {
            const Vec3 p = centre + 0.3 * (u(rng) * t1 + u(rng) * t2);
            r.rows.push_back({n, p.cross(n)});
        }
        r.rows.push_back({t1, centre.cross(t1)});
        r.rows.push_back({t2, centre.cross(t2)});
        r.rows.push_back({Vec3::Zero(), 0.2 * n});
    }
    return r;
}

Eigen::MatrixXd columns(const std::vector<SupportRow>& rows) {
    Eigen::MatrixXd w(6, static_cast<Eigen::Index>(rows.size()));
    for (std::size_t i = 0; i < rows.size(); ++i)
        w.col(static_cast<Eigen::Index>(i)) << rows[i].linear, rows[i].angular;
    return w;
}

void expectAgainstSvd(int patches, bool consistent, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int trial = 0; trial < 100; ++trial) {
        const RandomRows r = randomRows(rng, patches);
        const int count = static_cast<int>(r.rows.size());
        const Eigen::MatrixXd w = columns(r.rows);
        Eigen::VectorXd e(count);
        if (consistent) {
            Eigen::Matrix<double, 6, 1> du;
            for (int i = 0; i < 6; ++i) du(i) = u(rng);
            e = w.transpose() * du;
        } else {
            for (int i = 0; i < count; ++i) e(i) = u(rng);
        }
        SupportBlock block;
        ASSERT_TRUE(block.factor(r.rows.data(), count, r.inv_mass, r.inv_inertia));
        Vec3 dv, dw;
        std::vector<double> p(static_cast<std::size_t>(count));
        block.solve(r.rows.data(), e.data(), dv, dw, p.data());
        // The reference: least squares for du, minimum norm for p.
        Eigen::MatrixXd m_inv = Eigen::MatrixXd::Zero(6, 6);
        m_inv.topLeftCorner(3, 3) = r.inv_mass * Mat3::Identity();
        m_inv.bottomRightCorner(3, 3) = r.inv_inertia;
        const Eigen::JacobiSVD<Eigen::MatrixXd> fit(w.transpose(), Eigen::ComputeThinU | Eigen::ComputeThinV);
        const Eigen::VectorXd du_ref = fit.solve(e);
        Eigen::JacobiSVD<Eigen::MatrixXd> svd(w.transpose() * m_inv * w, Eigen::ComputeFullU | Eigen::ComputeFullV);
        svd.setThreshold(1e-10);
        Eigen::VectorXd target = e;
        if (!consistent) target = w.transpose() * du_ref;   // the part of e one motion meets
        const Eigen::VectorXd p_ref = svd.solve(target);
        const double scale = 1.0 + p_ref.cwiseAbs().maxCoeff();
        const double du_scale = 1.0 + du_ref.cwiseAbs().maxCoeff();
        for (int i = 0; i < 3; ++i) {
            EXPECT_NEAR(dv(i), du_ref(i), 1e-9 * du_scale) << "seed " << seed << " trial " << trial;
            EXPECT_NEAR(dw(i), du_ref(3 + i), 1e-9 * du_scale) << "seed " << seed << " trial " << trial;
        }
        for (int i = 0; i < count; ++i)
            EXPECT_NEAR(p[static_cast<std::size_t>(i)], p_ref(i), 1e-8 * scale)
                << "seed " << seed << " trial " << trial << " row " << i;
    }
}

TEST(SupportBlock, OnePatchMatchesTheAssembledSystem) { expectAgainstSvd(1, true, 31); }
TEST(SupportBlock, TwoPatchesMatchTheAssembledSystem) { expectAgainstSvd(2, true, 32); }
TEST(SupportBlock, FourPatchesMatchTheAssembledSystem) { expectAgainstSvd(4, true, 33); }
TEST(SupportBlock, TargetsNoMotionMeetsGetTheLeastSquaresMotion) { expectAgainstSvd(2, false, 34); }

TEST(SupportBlock, RowsThatLeaveADirectionFreeAreRefused) {
    std::mt19937_64 rng(35);
    RandomRows r = randomRows(rng, 1);
    r.rows.resize(4);   // four normal points only: the body may slide and spin in the patch's plane
    SupportBlock block;
    EXPECT_FALSE(block.factor(r.rows.data(), 4, r.inv_mass, r.inv_inertia));
    r = randomRows(rng, 4);
    r.rows.push_back(r.rows.front());   // 29 rows: more than a block takes
    EXPECT_FALSE(block.factor(r.rows.data(), static_cast<int>(r.rows.size()), r.inv_mass, r.inv_inertia));
}

// A 1 kg box, 0.6 m long, bridging two static blocks whose tops it overlaps over x in [-0.3, -0.2]
// and [0.1, 0.3], moving a little: shock propagation alone (no plain sweeps), from no impulses. The
// box must be at rest after its first shock sweep (the second changes nothing): its impulse takes
// away its momentum and gravity's m g h (closed form). The split over the patches' rows (eight
// normal points, friction along t1 and t2 at each centroid, spin scaled by the torsion radius) must
// be the minimum-norm one, from the assembled 14-row system solved by SVD.
TEST(SupportBlock, ABoxBridgingTwoBlocksRestsInOneShockSweepWithTheMinimumNormSplit) {
    auto block = [](const Vec3& half, const Vec3& centre, bool fixed) {
        Body b;
        b.role = fixed ? BodyRole::Real : BodyRole::Virtual;
        b.shape = Shape::box(half);
        if (!fixed) b.mass_properties = massProperties(b.shape, 1.0);
        b.pose = at(centre);
        return RigidBody::fromScene(b);
    };
    std::vector<RigidBody> bodies = {block(Vec3(0.2, 0.2, 0.2), Vec3(-0.4, 0.0, -0.2), true),
                                     block(Vec3(0.2, 0.2, 0.2), Vec3(0.3, 0.0, -0.2), true),
                                     block(Vec3(0.3, 0.1, 0.05), Vec3(0.0, 0.0, 0.05), false)};
    const RigidBody& box = bodies[2];
    bodies[2].velocity = Vec3(0.01, -0.02, -0.03);
    auto patch = [](int a, double x0, double x1) {
        ContactManifold m;
        m.body_a = a;
        m.body_b = 2;
        m.normal = Vec3::UnitZ();
        m.distance = 0.0;
        m.friction = 0.6;
        for (const double x : {x0, x1})
            for (const double y : {-0.1, 0.1}) {
                m.points.push_back(Vec3(x, y, 0.0));
                m.point_gap.push_back(0.0);
            }
        m.centroid = Vec3(0.5 * (x0 + x1), 0.0, 0.0);
        return m;
    };
    std::vector<ContactManifold> manifolds;
    manifolds.push_back(patch(0, -0.3, -0.2));
    manifolds.push_back(patch(1, 0.1, 0.3));
    ContactSolverSettings s;
    s.iterations = 0;   // no plain sweeps: the shock sweeps do it all
    s.warm_start = false;
    s.correction_iterations = 0;
    const double h = 1.0 / 60.0;
    const Vec3 g(0.0, 0.0, -9.81);
    std::vector<BodyImpulse> impulses;
    const ContactSolverReport report = solveContactPhase(bodies, manifolds, h, g, s, impulses);
    EXPECT_EQ(report.shock_sweeps, 2);
    const Vec3 stop = -(box.velocity + g * h) / box.inv_mass;
    EXPECT_NEAR((impulses[2].linear - stop).norm(), 0.0, 1e-12);
    EXPECT_NEAR(impulses[2].angular.norm(), 0.0, 1e-12);
    // The assembled rows of the two patches on the box and their minimum-norm impulses.
    std::vector<Eigen::Matrix<double, 6, 1>> rows;
    for (const ContactManifold& m : manifolds) {
        const Vec3 n = m.normal, t1 = n.unitOrthogonal(), t2 = n.cross(t1), c = m.centroid - box.com;
        double mean = 0.0;
        for (const Vec3& p : m.points) {
            Eigen::Matrix<double, 6, 1> r;
            r << n, (p - box.com).cross(n);
            rows.push_back(r);
            mean += (p - m.centroid).norm() / static_cast<double>(m.points.size());
        }
        for (const Vec3& t : {t1, t2}) {
            Eigen::Matrix<double, 6, 1> r;
            r << t, c.cross(t);
            rows.push_back(r);
        }
        Eigen::Matrix<double, 6, 1> spin;
        spin << Vec3::Zero(), (2.0 / 3.0) * mean * n;
        rows.push_back(spin);
    }
    Eigen::MatrixXd j(static_cast<Eigen::Index>(rows.size()), 6);
    for (std::size_t i = 0; i < rows.size(); ++i) j.row(static_cast<Eigen::Index>(i)) = rows[i].transpose();
    Eigen::Matrix<double, 6, 6> m_inv = Eigen::Matrix<double, 6, 6>::Zero();
    m_inv.topLeftCorner<3, 3>() = box.inv_mass * Mat3::Identity();
    m_inv.bottomRightCorner<3, 3>() = box.invInertiaWorld();
    Eigen::Matrix<double, 6, 1> u;
    u << box.velocity + g * h, Vec3::Zero();
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(j * m_inv * j.transpose(), Eigen::ComputeFullU | Eigen::ComputeFullV);
    svd.setThreshold(1e-10);
    const Eigen::VectorXd p = svd.solve(Eigen::VectorXd(-(j * u)));
    Eigen::Index r = 0;
    for (const ContactManifold& m : manifolds) {
        for (const double lambda : m.point_impulse) EXPECT_NEAR(lambda, p(r++), 1e-12) << "row " << r - 1;
        const Vec3 t1 = m.normal.unitOrthogonal(), t2 = m.normal.cross(t1);
        EXPECT_NEAR(m.tangent_impulse.dot(t1), p(r), 1e-12);
        EXPECT_NEAR(m.tangent_impulse.dot(t2), p(r + 1), 1e-12);
        double mean = 0.0;   // the spin row's impulse is the torsion impulse over the torsion radius
        for (const Vec3& q : m.points) mean += (q - m.centroid).norm() / static_cast<double>(m.points.size());
        EXPECT_NEAR(m.torsion_impulse, p(r + 2) * (2.0 / 3.0) * mean, 1e-12);
        r += 3;
    }
}

}  // namespace
}  // namespace vroc::native::test
