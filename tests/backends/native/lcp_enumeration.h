// SPDX-License-Identifier: MIT
// A brute-force answer to a small linear complementarity problem w = M x + q >= 0, x >= 0,
// x.w = 0 (a contact patch's normal impulses): every active set tried, each solved for the minimum
// norm by a complete orthogonal decomposition. For the tests of the patch impulse and of the normal
// problem's solvers, independent of both.
#pragma once

#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/QR>

namespace vroc::native::test {

// The rows and columns `rows` of M x + q = 0 solved (minimum norm), x zero elsewhere.
inline Eigen::VectorXd solveOnRows(const Eigen::MatrixXd& m, const Eigen::VectorXd& q, const std::vector<int>& rows) {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(q.size());
    if (rows.empty()) return x;
    Eigen::MatrixXd ma(rows.size(), rows.size());
    Eigen::VectorXd qa(rows.size());
    for (std::size_t r = 0; r < rows.size(); ++r) {
        qa(static_cast<Eigen::Index>(r)) = -q(rows[r]);
        for (std::size_t c = 0; c < rows.size(); ++c) ma(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = m(rows[r], rows[c]);
    }
    const Eigen::VectorXd xa = ma.completeOrthogonalDecomposition().solve(qa);
    for (std::size_t r = 0; r < rows.size(); ++r) x(rows[r]) = xa(static_cast<Eigen::Index>(r));
    return x;
}

// The complementary answer of least norm over every active set (N <= 8; unique for a definite M),
// feasible to `tol`; empty if none is.
inline Eigen::VectorXd enumerateLcp(const Eigen::MatrixXd& m, const Eigen::VectorXd& q, double tol = 1e-9) {
    const int n = static_cast<int>(q.size());
    Eigen::VectorXd best;
    double best_norm = std::numeric_limits<double>::infinity();
    for (int mask = 0; mask < (1 << n); ++mask) {
        std::vector<int> act;
        for (int i = 0; i < n; ++i)
            if (mask >> i & 1) act.push_back(i);
        const Eigen::VectorXd x = solveOnRows(m, q, act);
        const Eigen::VectorXd w = m * x + q;
        if (x.minCoeff() < -tol || w.minCoeff() < -tol) continue;
        if (std::abs(x.dot(w)) > tol) continue;
        if (x.norm() < best_norm) {
            best_norm = x.norm();
            best = x;
        }
    }
    return best;
}

}  // namespace vroc::native::test
