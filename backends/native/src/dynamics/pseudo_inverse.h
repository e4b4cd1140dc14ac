// SPDX-License-Identifier: MIT
// The minimum-norm inverse of a small normal block (internal; contact_solver.cpp). In its own
// file because Eigen's complete orthogonal decomposition, unrolled for 2x2, 3x3 and 4x4, is
// three quarters of the contact solver's compile time (31 of 43 s): here it compiles beside the
// rest instead of after it (issue 26).
#pragma once

#include <Eigen/Core>

namespace vroc::native {

/// The minimum-norm (Moore-Penrose) inverse of the top-left n x n block of `m`, n = 2..4, into the
/// top-left corner of `inv` (the rest of `inv` is left as it was). Fixed-size for each n, so the
/// decomposition unrolls and allocates nothing.
void pseudoInverseInto(int n, const Eigen::Matrix4d& m, Eigen::Matrix4d& inv);

}  // namespace vroc::native
