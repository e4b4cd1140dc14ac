// SPDX-License-Identifier: MIT
// Phantom box-box contacts (mujoco.bound_box_depth). MuJoCo 2.2's box-box collider
// (engine_collision_box.c) can pick an edge-edge separating axis in the near-tie that two boxes
// resting face to face produce, and its edge-edge routine then returns a contact about a box width
// deep beside the real ones (google-deepmind/mujoco issue #3476, reported for 3.10 and fixed on
// main in 2026 by bounding the depth by the separating-axis overlap). One such contact throws a
// resting stack apart (measured: a 10-box stack, elliptic cone, a contact 0.156 m deep between the
// top two boxes at t = 0.64 s, the top box at 30 rad/s one step later). No contact between two
// boxes can be deeper than their overlap along its own normal n:
//     r_a(n) + r_b(n) - |(c_b - c_a) . n|,   r(n) = sum_i h_i |u_i . n|  (h_i half extents, u_i axes).
// boundBoxDepths() clamps every box-box contact to that overlap (a contact that is then no longer
// within the model's margin is excluded, as mj_collision would have) and, if it changed any,
// rebuilds the constraint rows from the corrected list (mj_makeConstraint, mj_projectConstraint).
#pragma once

#include <mujoco/mujoco.h>

namespace vroc::mujoco {

/// Name of the MJCF <custom><numeric> that switches the bound on (value 1).
inline constexpr const char* kBoxDepthBoundName = "vroc_box_depth_bound";

/// [m] Overlap of two boxes along the unit normal n (negative when they are apart along n).
double boxOverlap(const mjModel* m, const mjData* d, int geom_a, int geom_b, const mjtNum n[3]);

/// Clamps the box-box contacts of `d` as described above; returns how many it changed. Runs
/// after mj_makeConstraint (MuJoCo's passive-force callback), so it rebuilds the rows itself.
int boundBoxDepths(const mjModel* m, mjData* d);

}  // namespace vroc::mujoco
