// SPDX-License-Identifier: MIT
#include "sized_lcp_solver.h"

namespace vroc::dart {

const std::string& SizedBoxedLcpSolver::getType() const {
    static const std::string type = "vroc::dart::SizedBoxedLcpSolver";
    return type;
}

bool SizedBoxedLcpSolver::solve(int n, double* A, double* x, double* b, int nub, double* lo, double* hi, int* findex,
                                bool earlyTermination) {
    if (n > max_rows_) {
        ++pgs_solves_;
        return pgs_.solve(n, A, x, b, nub, lo, hi, findex, earlyTermination);
    }
    const bool solved = dantzig_.solve(n, A, x, b, nub, lo, hi, findex, earlyTermination);
    if (!solved) ++dantzig_failures_;
    return solved;
}

bool SizedBoxedLcpSolver::canSolve(int n, const double* A) {
    (void)A;
    return n > 0;  // both solvers take any square system DART builds
}

}  // namespace vroc::dart
