// SPDX-License-Identifier: MIT
#include "mujoco_config.h"

namespace vroc::mujoco {

std::vector<SettingSpec> mujocoSettingSpecs() {
    using T = SettingSpec::Type;
    return {
        {"mujoco.timestep", T::Real, "0.002", 1e-6, 1.0, {},
         "[s] largest internal step (MuJoCo default 0.002); a frame is split into equal steps no longer than this"},
        {"mujoco.contact_timeconst", T::Real, "0.006", 1e-5, 1.0, {},
         "[s] time constant of the contact spring (natural frequency 1/tc); at least 2 x mujoco.timestep"},
        {"mujoco.restitution", T::Choice, "solref", 0, 0, {"solref", "default"},
         "solref: each pair's restitution mapped onto its solref; default: MuJoCo's solref (0.02, 1), no restitution"},
        {"mujoco.max_substeps", T::Integer, "100000", 1, 1e9, {},
         "internal steps allowed per frame; a longer frame takes steps of dt / max_substeps"},
        {"mujoco.substeps", T::Integer, "0", 0, 1e6, {},
         "internal steps per frame, fixed (0: from mujoco.timestep); the contact time constant is then raised to 2 x "
         "the step where shorter (MuJoCo's rule). Set by --footing equal"},
        {"mujoco.cone", T::Choice, "pyramidal", 0, 0, {"pyramidal", "elliptic"},
         "friction cone (MuJoCo default pyramidal: 4 edges, mu/sqrt2 along their diagonals; elliptic: Coulomb's "
         "circle)"},
        {"mujoco.impratio", T::Real, "1", 1e-3, 1e3, {},
         "[-] friction-to-normal impedance ratio (MuJoCo default 1); > 1 makes sticking friction stiffer"},
        {"mujoco.noslip_iterations", T::Integer, "0", 0, 1000, {},
         "iterations of MuJoCo's noslip post-solver on the friction rows (MuJoCo default 0: off)"},
        {"mujoco.integrator", T::Choice, "euler", 0, 0, {"euler", "rk4", "implicit"},
         "integrator (MuJoCo 2.2's mjtIntegrator; default euler: semi-implicit Euler; rk4; implicit in velocity)"},
        {"mujoco.bound_box_depth", T::Boolean, "false", 0, 0, {},
         "clamp box-box contacts to the boxes' overlap along the normal (MuJoCo 2.2's collider returns phantom "
         "contacts ~a box width deep; default false: its contacts as they are)"},
    };
}

MujocoConfig MujocoConfig::from(const Settings& s) {
    MujocoConfig c;
    c.timestep = s.real("mujoco.timestep");
    c.contact_timeconst = s.real("mujoco.contact_timeconst");
    c.restitution = s.text("mujoco.restitution");
    c.max_substeps = static_cast<int>(s.integer("mujoco.max_substeps"));
    c.substeps = static_cast<int>(s.integer("mujoco.substeps"));
    c.cone = s.text("mujoco.cone");
    c.impratio = s.real("mujoco.impratio");
    c.noslip_iterations = static_cast<int>(s.integer("mujoco.noslip_iterations"));
    c.integrator = s.text("mujoco.integrator");
    c.bound_box_depth = s.boolean("mujoco.bound_box_depth");
    return c;
}

}  // namespace vroc::mujoco
