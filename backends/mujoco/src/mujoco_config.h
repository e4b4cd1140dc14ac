// SPDX-License-Identifier: MIT
// The MuJoCo backend's `--set` keys and their parsed values (docs/mujoco-backend.md explains each).
#pragma once

#include <string>
#include <vector>

#include "vroc/core/settings.h"

namespace vroc::mujoco {

struct MujocoConfig {
    /// [s] largest internal step. A frame of dt is n = ceil(dt / timestep) equal steps of dt / n
    /// (MuJoCo's default timestep is 0.002 s; equal steps keep frame ends on the step grid).
    double timestep = 0.002;
    /// [s] time constant tc of the contact's reference spring: natural frequency 1 / tc. The
    /// damping ratio comes from the pair's restitution (restitution_mapping.h).
    double contact_timeconst = 0.006;
    /// "solref": restitution mapped onto each pair's solref; "default": MuJoCo's default solref
    /// (0.02 s, damping ratio 1) for every pair, restitution ignored.
    std::string restitution = "solref";
    /// Internal steps allowed per frame; a longer frame takes steps of dt / max_substeps.
    int max_substeps = 100000;
    /// Internal steps per frame, fixed (0: from `timestep`). Set by the equal footing of a fair
    /// comparison (every engine K steps a frame); then the restitution mapping is made for the step
    /// dt / substeps and the contact time constant is raised to 2 x that step where it is shorter
    /// (MuJoCo's own rule for a stable contact spring, which its solver would otherwise apply).
    int substeps = 0;
    /// Friction cone (mjModel opt.cone): "pyramidal" (MuJoCo's default: 4 edges for condim 3, the
    /// square inscribed in Coulomb's circle) or "elliptic" (Coulomb's circular cone, solved as a
    /// second-order cone by MuJoCo's Newton solver).
    std::string cone = "pyramidal";
    /// [-] ratio of the friction rows' impedance to the normal row's (opt.impratio, MuJoCo's
    /// default 1): the friction rows' regulariser R is the normal row's divided by it, so > 1
    /// makes friction stiffer (less creep in sticking contacts).
    double impratio = 1.0;
    /// Iterations of MuJoCo's noslip post-solver (opt.noslip_iterations, MuJoCo's default 0 =
    /// off): a projected Gauss-Seidel pass on the friction rows without regularisation, which
    /// removes the slip the soft friction constraint allows.
    int noslip_iterations = 0;
    /// Integrator (opt.integrator; MuJoCo 2.2's mjtIntegrator): "euler" (semi-implicit Euler,
    /// MuJoCo's default), "rk4" (4th-order Runge-Kutta) or "implicit" (implicit in velocity).
    std::string integrator = "euler";
    /// Box-box contacts deeper than the two boxes' overlap along their normal are clamped to it
    /// (box_depth_bound.h: MuJoCo 2.2's box-box collider can return phantom contacts about a box
    /// width deep). false: MuJoCo's contacts as its collider returns them.
    bool bound_box_depth = false;

    static MujocoConfig from(const Settings& settings);
};

/// The declared keys, with types, ranges, defaults (those of MujocoConfig) and help lines.
std::vector<SettingSpec> mujocoSettingSpecs();

}  // namespace vroc::mujoco
