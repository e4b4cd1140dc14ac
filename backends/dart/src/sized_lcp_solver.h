// SPDX-License-Identifier: MIT
// The boxed LCP solver of each constrained group (a set of touching bodies): DART's default,
// the pivoting Dantzig solver, for groups of up to `dantzig_max_rows` rows, and DART's projected
// Gauss-Seidel beyond. DART builds and solves a dense n x n system per group, and Dantzig is
// O(n^3): a 56-box pyramid (about 1,200 rows) took 0.16 s per step, with FCL's mesh contacts
// (3,300 rows) 6 s per step (docs/dart-backend.md). Every failure of the Dantzig solve (DART then
// tries its secondary solver, PGS) is counted.
//
// ABI note: Debian builds libdart without NDEBUG, and BoxedLcpSolver declares the virtual
// canSolve() only without NDEBUG; this class declares it whatever NDEBUG says, so that its vtable
// has the library's layout.
#pragma once

#include <cstdint>
#include <dart/constraint/BoxedLcpSolver.hpp>
#include <dart/constraint/DantzigBoxedLcpSolver.hpp>
#include <dart/constraint/PgsBoxedLcpSolver.hpp>
#include <memory>
#include <string>

namespace vroc::dart {

class SizedBoxedLcpSolver final : public ::dart::constraint::BoxedLcpSolver {
public:
    /// `dantzig_max_rows`: the largest group solved by Dantzig (0: every group by PGS).
    explicit SizedBoxedLcpSolver(int dantzig_max_rows) : max_rows_(dantzig_max_rows) {}

    const std::string& getType() const override;
    bool solve(int n, double* A, double* x, double* b, int nub, double* lo, double* hi, int* findex,
               bool earlyTermination) override;
    // Without `override`: the base declares it only when NDEBUG is not defined (see above).
    virtual bool canSolve(int n, const double* A);  // NOLINT(modernize-use-override)

    std::uint64_t dantzigFailures() const { return dantzig_failures_; }
    std::uint64_t pgsSolves() const { return pgs_solves_; }

private:
    int max_rows_;
    ::dart::constraint::DantzigBoxedLcpSolver dantzig_;
    ::dart::constraint::PgsBoxedLcpSolver pgs_;
    std::uint64_t dantzig_failures_ = 0, pgs_solves_ = 0;
};

}  // namespace vroc::dart
