// SPDX-License-Identifier: MIT
// One body held by rows whose other bodies do not move, solved at once (internal;
// contact_solver.cpp). In a level of shock propagation the levels below are frozen, so a box on
// two boxes is a single body against fixed rows: its two patches' normal points, friction and spin.
// Gauss-Seidel over those rows, patch after patch, closes the error by a constant factor a sweep
// (about 0.37 for a box over two others: each patch's normals, friction and spin undo part of what
// the others did), so a tall pile's levels took 20 to 30 sweeps each. This takes the limit at once.
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "vroc/core/math.h"

namespace vroc::native {

/// A row on one body: a unit impulse along it applies the force `linear` and the moment `angular`
/// about the body's centre of mass; the same two vectors read the velocity along the row off the
/// body's velocity change (linear . dv + angular . dw).
struct SupportRow {
    Vec3 linear = Vec3::Zero();
    Vec3 angular = Vec3::Zero();
};

/// The most rows a block takes (four patches of four points, friction and spin).
constexpr int kMaxSupportRows = 28;

/// Rows W (as columns) on one body of mass M. For row errors e it gives the velocity change
/// du = (dv, dw) that fits W^T du = e in the least-squares sense, du = H^-1 W e with H = W W^T, and
/// the impulses of least norm that make it, p = W^T H^-1 M du (then W p = M du). With consistent
/// errors (rows that one rigid motion satisfies) du meets every row: the limit of Gauss-Seidel over
/// them, in one step, with the load shared evenly by redundant rows.
class SupportBlock {
  public:
    /// Factors H; false (the block is unusable) when the rows do not span all six directions of
    /// motion or there are more than kMaxSupportRows of them.
    bool factor(const SupportRow* rows, int count, double inv_mass, const Mat3& inv_inertia);
    /// e[0, count) are the rows' errors [m/s]: what each row's velocity lacks of its target.
    /// Writes the velocity change and p[0, count).
    void solve(const SupportRow* rows, const double* e, Vec3& dv, Vec3& dw, double* p) const;
    int count() const { return count_; }

  private:
    Eigen::Matrix<double, 6, 1> solveH(const Eigen::Matrix<double, 6, 1>& x) const;   // H^-1 x

    Eigen::LLT<Eigen::Matrix<double, 6, 6>> h_;   // of S H S
    Eigen::Matrix<double, 6, 1> scale_ = Eigen::Matrix<double, 6, 1>::Ones();   // S
    double mass_ = 0.0;
    Mat3 inertia_ = Mat3::Zero();
    int count_ = 0;
};

}  // namespace vroc::native
