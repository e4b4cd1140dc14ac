// SPDX-License-Identifier: MIT
// The normal impulses of a contact patch's impact: the linear complementarity problem
// w = M y + q >= 0, y >= 0, y.w = 0 over its points, M (symmetric, positive semi-definite) the
// relative normal speed change at each point per unit normal impulse at each, q the normal speeds
// less their targets. Solved exactly: in closed form for one or two points, by Lawson and
// Hanson's active-set method otherwise (and where two points' block is nearly singular), with the
// minimum-norm split where the answer is not unique (a flat box's four corners).
#pragma once

#include <Eigen/Core>

#include "dynamics/contact.h"

namespace vroc::native {

/// At most this many points: a manifold's (four touching and four speculative).
constexpr int kMaxLcpPoints = static_cast<int>(kMaxManifoldSlots);
using LcpMatrix = Eigen::Matrix<double, kMaxLcpPoints, kMaxLcpPoints>;
using LcpVector = Eigen::Matrix<double, kMaxLcpPoints, 1>;

/// The solution over the first `count` points (zero beyond): the closed form where it applies,
/// the active-set method otherwise. All NaN if an entry of the problem is not finite.
LcpVector solveNormalLcp(const LcpMatrix& m, const LcpVector& q, int count);

/// The active-set method alone, for any `count` up to kMaxLcpPoints.
LcpVector solveNormalLcpByActiveSet(const LcpMatrix& m, const LcpVector& q, int count);

/// One or two points in closed form: each complementarity case tried in turn. False (y is then
/// not an answer) for more points, a non-finite entry, a non-positive diagonal or a nearly
/// singular pair: the active-set method decides those.
bool solveSmallNormalLcp(const LcpMatrix& m, const LcpVector& q, int count, LcpVector& y);

}  // namespace vroc::native
