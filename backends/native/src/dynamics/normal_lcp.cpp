// SPDX-License-Identifier: MIT
#include "dynamics/normal_lcp.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <Eigen/Cholesky>
#include <Eigen/QR>

namespace vroc::native {
namespace {

constexpr int kMaxPoints = kMaxLcpPoints;
using Block = LcpMatrix;
using BlockVector = LcpVector;
using SubMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxPoints, kMaxPoints>;
using SubVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxPoints, 1>;
using FreeSet = std::array<bool, kMaxPoints>;
using Indices = std::array<int, kMaxPoints>;

// The rows and columns `idx[0..k)` of m, and -q there.
void gatherFreeSet(const Block& m, const BlockVector& q, const Indices& idx, int k, Block& mf, BlockVector& rhs) {
    for (int r = 0; r < k; ++r) {
        rhs(r) = -q(idx[static_cast<std::size_t>(r)]);
        for (int c = 0; c < k; ++c) mf(r, c) = m(idx[static_cast<std::size_t>(r)], idx[static_cast<std::size_t>(c)]);
    }
}

int freeIndices(const FreeSet& free, int count, Indices& idx) {
    int k = 0;
    for (int i = 0; i < count; ++i)
        if (free[static_cast<std::size_t>(i)]) idx[static_cast<std::size_t>(k++)] = i;
    return k;
}

// LDL' of the leading k x k block of a symmetric matrix, in place, without pivoting: for the
// active set's inner solves, whose blocks the ridge below makes positive definite (at most eight
// rows: no dynamic-size factorisation and no allocation). False if a pivot is not positive.
bool factorLdlt(Block& a, int k) {
    for (int j = 0; j < k; ++j) {
        double d = a(j, j);
        for (int p = 0; p < j; ++p) d -= a(j, p) * a(j, p) * a(p, p);
        if (!(d > 0.0)) return false;
        a(j, j) = d;
        for (int i = j + 1; i < k; ++i) {
            double x = a(i, j);
            for (int p = 0; p < j; ++p) x -= a(i, p) * a(j, p) * a(p, p);
            a(i, j) = x / d;
        }
    }
    return true;
}

// Solves with factorLdlt's factors, in place.
void solveLdlt(const Block& a, int k, BlockVector& x) {
    for (int i = 0; i < k; ++i)
        for (int p = 0; p < i; ++p) x(i) -= a(i, p) * x(p);
    for (int i = 0; i < k; ++i) x(i) /= a(i, i);
    for (int i = k - 1; i >= 0; --i)
        for (int p = i + 1; p < k; ++p) x(i) -= a(p, i) * x(p);
}

// The free points' subsystem M_ff z_f = -q_f (M positive definite), its answer scattered back to
// all points in `z`, zero elsewhere; false if the factorisation fails.
bool solveOnFreeSet(const Block& m, const BlockVector& q, const Indices& idx, int k, BlockVector& z) {
    Block mf;
    BlockVector rhs;
    gatherFreeSet(m, q, idx, k, mf, rhs);
    if (!factorLdlt(mf, k)) return false;
    solveLdlt(mf, k, rhs);
    z = BlockVector::Zero();
    for (int r = 0; r < k; ++r) z(idx[static_cast<std::size_t>(r)]) = rhs(r);
    return true;
}

// The minimum-norm solution of a free set's subsystem: a clearly definite block (its pivoted LDL'
// pivots within 1e-10 of each other: three points not on a line) has one solution, found by the
// factorisation; a singular or nearly singular one (four coplanar points, three on a line) takes the
// complete orthogonal decomposition, whose answer is the symmetric split. Eigen's LDLT here, not
// factorLdlt: whether a block counts as definite is decided on pivots in descending order (without
// pivoting the ratio differs, and splits that should be symmetric were not: the ball into the
// base-12 pyramid went 11 -> 20 mm deep on fixed ticks). Once per complementarity solve.
BlockVector minimumNormOnFreeSet(const Block& m, const BlockVector& q, const Indices& idx, int k) {
    Block mf;
    BlockVector rhs;
    gatherFreeSet(m, q, idx, k, mf, rhs);
    const SubMatrix sub = mf.topLeftCorner(k, k);
    const SubVector b = rhs.head(k);
    const Eigen::LDLT<SubMatrix> ldlt(sub);
    const auto d = ldlt.vectorD().cwiseAbs();
    const bool definite = ldlt.info() == Eigen::Success && ldlt.isPositive() && d.minCoeff() > 1e-10 * d.maxCoeff();
    const SubVector x = definite ? SubVector(ldlt.solve(b)) : SubVector(Eigen::CompleteOrthogonalDecomposition<SubMatrix>(sub).solve(b));
    BlockVector z = BlockVector::Zero();
    for (int r = 0; r < k; ++r) z(idx[static_cast<std::size_t>(r)]) = x(r);
    return z;
}

// w = M y + q over the first `count` points.
BlockVector residual(const Block& m, const BlockVector& y, const BlockVector& q, int count) {
    BlockVector w = BlockVector::Zero();
    for (int i = 0; i < count; ++i) {
        double x = q(i);
        for (int j = 0; j < count; ++j) x += m(i, j) * y(j);
        w(i) = x;
    }
    return w;
}

}  // namespace

// One or two points in closed form: each complementarity case (no impulse, both points pushing,
// one) tried in turn, the first that holds returned. A positive definite M has exactly one
// solution, the one the active-set method finds (up to rounding), so this is that method without
// its factorisations: most patches the collision phase meets are an edge's two points, and a
// sliding one solves the problem at every pass of its friction's fixed point. A nearly singular
// pair is left to the general method (its minimum-norm split), and so is a non-finite entry (it
// reports it).
bool solveSmallNormalLcp(const LcpMatrix& m, const LcpVector& q, int count, LcpVector& y) {
    if (count < 1 || count > 2) return false;
    if (!q.head(count).allFinite() || !m.topLeftCorner(count, count).allFinite()) return false;
    const double scale = q.head(count).cwiseAbs().maxCoeff() + 1e-300;
    const double tol = 1e-12 * scale;
    y = BlockVector::Zero();
    if (count == 1) {
        if (!(m(0, 0) > 0.0)) return false;
        if (q(0) < -tol) y(0) = -q(0) / m(0, 0);
        return true;
    }
    const double m00 = m(0, 0), m01 = m(0, 1), m10 = m(1, 0), m11 = m(1, 1);
    const double det = m00 * m11 - m01 * m10;
    // The general method's test of a definite block: its pivots within 1e-10 of each other.
    if (!(m00 > 0.0) || !(m11 > 0.0) || !(det > 1e-10 * std::max(m00, m11) * std::max(m00, m11))) return false;
    if (!(q(0) < -tol) && !(q(1) < -tol)) return true;   // nothing approaches: no impulse
    const double y0 = (-q(0) * m11 + q(1) * m01) / det, y1 = (-q(1) * m00 + q(0) * m10) / det;
    if (y0 > 0.0 && y1 > 0.0) {
        y(0) = y0;
        y(1) = y1;
        return true;
    }
    // One point pushes, the more violated first; the other must then not approach.
    const int first = q(0) <= q(1) ? 0 : 1;
    for (int i : {first, 1 - first}) {
        const int j = 1 - i;
        if (!(q(i) < -tol)) continue;
        const double yi = -q(i) / m(i, i);
        if (q(j) + m(j, i) * yi >= -tol) {
            y(i) = yi;
            return true;
        }
    }
    return false;
}

// The frictionless patch problem is the LCP w = M y + q >= 0, y >= 0, y.w = 0 with M symmetric
// positive semi-definite: the optimality conditions of min 1/2 y'My + q'y over y >= 0. Solved
// exactly by the active-set method of Lawson and Hanson's NNLS (1974, ch. 23) applied to that
// quadratic programme: free points are solved as a block (their speeds brought to the targets), a
// point whose impulse would turn negative leaves the set by the largest feasible step, the most
// violated point joins it. Finite for these sizes; the iteration cap guards rounding cycles.
LcpVector solveNormalLcpByActiveSet(const LcpMatrix& m_in, const LcpVector& q, int count) {
    // Four or more coplanar points make M singular (a rigid pair has three normal degrees of
    // freedom): a tiny ridge makes it definite, so the active set's subproblems always have one
    // solution, the limit of which is the minimum-norm split (a flat box's four equal impulses).
    // It moves the normal speeds by about 1e-12 of the impulses' scale.
    Block m = m_in;
    const double ridge = 1e-12 * m.diagonal().head(count).maxCoeff();
    for (int i = 0; i < count; ++i) m(i, i) += ridge;
    const double scale = q.head(count).cwiseAbs().maxCoeff() + 1e-300;
    const double tol = 1e-12 * scale;
    // From no impulse. (Starting from the last pass's impulses, which the method allows, was tried:
    // the 200-body mixed pile's penetration_recovered went from 13 to 153 in 4 s, so it is not used.)
    BlockVector y = BlockVector::Zero();
    FreeSet free{};
    Indices idx{};
    // Solves the free set, stepping back to the feasible region (dropping the points reaching 0)
    // until its solution pushes at every free point.
    auto solveFree = [&]() {
        for (int inner = 0; inner < 4 * kMaxPoints; ++inner) {
            const int k = freeIndices(free, count, idx);
            if (k == 0) return;
            BlockVector z;
            if (!solveOnFreeSet(m, q, idx, k, z) || !z.allFinite()) return;
            bool positive = true;
            for (int r = 0; r < k; ++r) positive = positive && z(idx[static_cast<std::size_t>(r)]) > 0.0;
            if (positive) {
                y = z;
                return;
            }
            // Step from y towards z as far as every free impulse stays >= 0; those reaching 0 leave.
            double alpha = 1.0;
            for (int r = 0; r < k; ++r) {
                const int i = idx[static_cast<std::size_t>(r)];
                if (z(i) <= 0.0) alpha = std::min(alpha, y(i) / (y(i) - z(i)));
            }
            y += alpha * (z - y);
            for (int r = 0; r < k; ++r) {
                const int i = idx[static_cast<std::size_t>(r)];
                if (y(i) <= tol * 1e-3) {
                    y(i) = 0.0;
                    free[static_cast<std::size_t>(i)] = false;
                }
            }
        }
    };
    for (int outer = 0; outer < 4 * kMaxPoints; ++outer) {
        const BlockVector w = residual(m, y, q, count);
        int join = -1;
        for (int i = 0; i < count; ++i)
            if (!free[static_cast<std::size_t>(i)] && w(i) < -tol && (join < 0 || w(i) < w(join))) join = i;
        if (join < 0) break;
        free[static_cast<std::size_t>(join)] = true;
        solveFree();
    }
    // The free set found, its impulses without the ridge: the minimum-norm solution there (exact
    // for the flat box's symmetric split), kept if it stays non-negative.
    const int k = freeIndices(free, count, idx);
    if (k == 0) return y;
    const BlockVector exact = minimumNormOnFreeSet(m_in, q, idx, k);
    if (!exact.allFinite()) return y;
    for (int r = 0; r < k; ++r)
        if (exact(idx[static_cast<std::size_t>(r)]) < 0.0) return y;
    return exact;
}

LcpVector solveNormalLcp(const LcpMatrix& m, const LcpVector& q, int count) {
    // A non-finite entry would fail every comparison of the methods and read as "nothing pushes".
    if (!q.head(count).allFinite() || !m.topLeftCorner(count, count).allFinite())
        return LcpVector::Constant(std::numeric_limits<double>::quiet_NaN());
    LcpVector y;
    if (solveSmallNormalLcp(m, q, count, y)) return y;
    return solveNormalLcpByActiveSet(m, q, count);
}

}  // namespace vroc::native
