// SPDX-License-Identifier: MIT
// The friction rows' reference damping under the elliptic cone (mujoco.cone=elliptic with the
// restitution mapping, mujoco.restitution=solref).
//
// MuJoCo 2.2 (engine_core_constraint.c, mj_makeImpedance) gives every row of an elliptic contact
// the damping B = -solref[1] / dmax of the contact's solref, and the friction rows stiffness 0: a
// friction row's reference acceleration is a_ref = -B v_t, and Coulomb friction exists in MuJoCo
// only through that term (the cone bounds the force). 2.2 has no separate friction solref for
// contacts. The restitution mapping (restitution_mapping.h) sets the pair's solref for the normal
// direction, so friction would follow e: at e = 1 B = 0 and a box sliding at 3 m/s never stops
// (measured); at e = 0.5 B is a sixth of e = 0's. So under the elliptic cone the friction rows get
// the damping the mapping gives a perfectly inelastic pair (e = 0: the cap B h = 1), whatever the
// pair's e, and the normal row keeps the pair's: friction is dissipative whatever the bounce, and
// at e = 0 the model is MuJoCo's own with the mapped solref, unchanged. Of the friction dampings
// measured (MuJoCo's default solref's 105 1/s, the critical damping at the contact time constant
// 351 1/s, this one 526 1/s at the defaults) this one slides most nearly isotropically (vroc
// check's 8 headings: 1.3 % spread against 2.7 % for MuJoCo's default), at the price of the lift
// MuJoCo's soft cone makes from B v_t (a box launched at 3 m/s is thrown up at 1 m/s in its first
// step, as under the pyramidal default at e = 0). It is set on efc_KBIP from the passive-force
// callback (passive_callback.h), after the rows are made and before their reference accelerations
// are. Under the pyramidal cone each row mixes normal and friction and nothing can be separated:
// the mapping's damping acts on friction too (docs/mujoco-backend.md).
#pragma once

#include <mujoco/mujoco.h>

namespace vroc::mujoco {

/// Name of the MJCF <custom><numeric> holding the friction rows' damping, direct solref form [1/s].
inline constexpr const char* kFrictionDampingName = "vroc_friction_damping";

/// Sets the damping of every friction row of every elliptic contact of `d` to damping / dmax
/// (MuJoCo's rule for a direct solref (-K, -damping)), dmax = the contact's solimp[1] as MuJoCo
/// clamps it. Called from the passive callback (passive_callback.h).
void setFrictionDamping(mjData* d, double damping);

}  // namespace vroc::mujoco
