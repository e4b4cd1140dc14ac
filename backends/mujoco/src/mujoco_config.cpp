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
    };
}

MujocoConfig MujocoConfig::from(const Settings& s) {
    MujocoConfig c;
    c.timestep = s.real("mujoco.timestep");
    c.contact_timeconst = s.real("mujoco.contact_timeconst");
    c.restitution = s.text("mujoco.restitution");
    c.max_substeps = static_cast<int>(s.integer("mujoco.max_substeps"));
    return c;
}

}  // namespace vroc::mujoco
