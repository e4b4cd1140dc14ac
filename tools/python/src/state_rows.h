// SPDX-License-Identifier: MIT
// One body's state as the 13 numbers of a row of the Python arrays, in the files' order:
// position x y z [m], orientation x y z w, linear velocity [m/s], angular velocity [rad/s] (world).
#pragma once

#include <span>
#include <string>
#include <vector>

#include "vroc/core/backend.h"

namespace vroc::python {

inline constexpr int kStateWidth = 13;
inline constexpr int kPositionColumn = 0;
inline constexpr int kOrientationColumn = 3;
inline constexpr int kLinearVelocityColumn = 7;
inline constexpr int kAngularVelocityColumn = 10;

void writeStateRow(const BodyState& state, double* row);
/// Throws InputError naming `body` unless every number is finite and the quaternion has unit norm
/// (within 1e-6; it is passed on as given, never renormalised, so a state read back is the same bits).
BodyState readStateRow(const double* row, const std::string& body);

/// `count` rows of kStateWidth numbers -> states, checked as readStateRow does.
std::vector<BodyState> readStateRows(std::span<const double> rows, const Scene& scene);

}  // namespace vroc::python
