// SPDX-License-Identifier: MIT
// MuJoCo's process-wide passive-force callback (mjcb_passive), used for what MuJoCo 2.2 offers no
// option for. mj_fwdVelocity calls it after the constraint rows are made (mj_fwdPosition:
// mj_collision, mj_makeConstraint, mj_projectConstraint) and before their reference accelerations
// (mj_referenceConstraint), in every evaluation of every integrator. What it does is switched on
// per model by <custom><numeric> entries the MJCF writer adds, so the callback keeps no state and a
// model without them is MuJoCo's own:
//  - vroc_box_depth_bound: phantom box-box contacts clamped (box_depth_bound.h);
//  - vroc_friction_damping, elliptic cone only: the friction rows' damping (friction_damping.h).
// It adds no passive force. Corrections are counted in mjData::userdata[0] when the model has room.
#pragma once

#include <mujoco/mujoco.h>

namespace vroc::mujoco {

/// Installs onPassive as mjcb_passive (idempotent; the MuJoCo backend is its only user).
void installPassiveCallback();

/// The callback.
void onPassive(const mjModel* m, mjData* d);

/// The <numeric> `name` of the model, or `fallback` if it has none.
double modelNumeric(const mjModel* m, const char* name, double fallback);

}  // namespace vroc::mujoco
