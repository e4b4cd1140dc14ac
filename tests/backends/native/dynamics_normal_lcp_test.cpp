// SPDX-License-Identifier: MIT
// The patch's normal complementarity problem (dynamics/normal_lcp.h): the closed form for one and
// two points against an enumeration of every active set solved by a complete orthogonal
// decomposition (an independent answer), and against the active-set method it stands in for; a
// nearly singular pair is left to that method, which splits the load evenly; non-finite input is
// reported, not hidden.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "dynamics/normal_lcp.h"
#include "lcp_enumeration.h"

namespace vroc::native::test {
namespace {

struct Problem {
    LcpMatrix m = LcpMatrix::Zero();
    LcpVector q = LcpVector::Zero();
};

// A random definite problem of `count` points: M = J J' + a small ridge, J random rows of a
// contact Jacobian's scale; q mixes approaching and separating points.
Problem randomProblem(std::mt19937_64& rng, int count) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Eigen::MatrixXd j(count, 6);
    for (int r = 0; r < count; ++r)
        for (int c = 0; c < 6; ++c) j(r, c) = u(rng);
    Problem p;
    p.m.topLeftCorner(count, count) = j * j.transpose() + 1e-3 * Eigen::MatrixXd::Identity(count, count);
    for (int i = 0; i < count; ++i) p.q(i) = u(rng);
    return p;
}

TEST(DynamicsNormalLcp, OneAndTwoPointsMatchTheEnumeratedSolutionAndTheActiveSetMethod) {
    std::mt19937_64 rng(22071);
    int closed = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const int count = 1 + trial % 2;
        const Problem p = randomProblem(rng, count);
        LcpVector small;
        ASSERT_TRUE(solveSmallNormalLcp(p.m, p.q, count, small)) << "trial " << trial;
        ++closed;
        const Eigen::VectorXd expect =
            enumerateLcp(p.m.topLeftCorner(count, count), p.q.head(count), 1e-9 * (1.0 + p.q.head(count).cwiseAbs().maxCoeff()));
        ASSERT_EQ(expect.size(), count) << "trial " << trial << ": no complementary answer";
        const LcpVector general = solveNormalLcpByActiveSet(p.m, p.q, count);
        const LcpVector dispatched = solveNormalLcp(p.m, p.q, count);
        for (int i = 0; i < count; ++i) {
            EXPECT_NEAR(small(i), expect(i), 1e-9 * (1.0 + std::abs(expect(i)))) << "trial " << trial << ", point " << i;
            EXPECT_NEAR(small(i), general(i), 1e-9 * (1.0 + std::abs(general(i)))) << "trial " << trial << ", point " << i;
            EXPECT_EQ(dispatched(i), small(i)) << "trial " << trial << ": the dispatch takes the closed form";
        }
        for (int i = count; i < kMaxLcpPoints; ++i) EXPECT_EQ(small(i), 0.0);
    }
    EXPECT_EQ(closed, 2000);
}

TEST(DynamicsNormalLcp, EveryComplementarityCaseOfTwoPointsIsMet) {
    // M = [[2, 1], [1, 2]]: both push; the first pushes, the second separates; the second pushes,
    // the first separates; the first pushes and its push lifts the second, which approached;
    // nothing approaches.
    LcpMatrix m = LcpMatrix::Zero();
    m(0, 0) = 2.0, m(0, 1) = 1.0, m(1, 0) = 1.0, m(1, 1) = 2.0;
    struct Case {
        double q0, q1, y0, y1;
    };
    for (const Case& c : {Case{-3.0, -3.0, 1.0, 1.0}, Case{-4.0, 1.0, 2.0, 0.0}, Case{3.0, -2.0, 0.0, 1.0},
                          Case{-2.0, -0.5, 1.0, 0.0}, Case{0.5, 0.25, 0.0, 0.0}}) {
        LcpVector q = LcpVector::Zero();
        q(0) = c.q0, q(1) = c.q1;
        LcpVector y;
        ASSERT_TRUE(solveSmallNormalLcp(m, q, 2, y));
        EXPECT_NEAR(y(0), c.y0, 1e-15) << "q = (" << c.q0 << ", " << c.q1 << ")";
        EXPECT_NEAR(y(1), c.y1, 1e-15) << "q = (" << c.q0 << ", " << c.q1 << ")";
    }
}

TEST(DynamicsNormalLcp, ANearlySingularPairIsLeftToTheActiveSetMethodWhichSplitsItEvenly) {
    // Two points whose rows are the same (both at one place): any split of the load stops them;
    // the minimum-norm one is even.
    LcpMatrix m = LcpMatrix::Zero();
    m(0, 0) = m(0, 1) = m(1, 0) = m(1, 1) = 0.5;
    LcpVector q = LcpVector::Zero();
    q(0) = q(1) = -1.0;
    LcpVector y;
    EXPECT_FALSE(solveSmallNormalLcp(m, q, 2, y));
    const LcpVector split = solveNormalLcp(m, q, 2);
    EXPECT_NEAR(split(0), 1.0, 1e-9);
    EXPECT_NEAR(split(1), 1.0, 1e-9);
}

TEST(DynamicsNormalLcp, NonFiniteInputIsReportedNotHidden) {
    LcpMatrix m = LcpMatrix::Identity();
    LcpVector q = LcpVector::Zero();
    q(0) = std::numeric_limits<double>::quiet_NaN();
    q(1) = -1.0;
    LcpVector y;
    EXPECT_FALSE(solveSmallNormalLcp(m, q, 2, y));
    EXPECT_FALSE(solveNormalLcp(m, q, 2).head(2).allFinite());
}

}  // namespace
}  // namespace vroc::native::test
