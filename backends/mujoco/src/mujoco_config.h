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

    static MujocoConfig from(const Settings& settings);
};

/// The declared keys, with types, ranges, defaults (those of MujocoConfig) and help lines.
std::vector<SettingSpec> mujocoSettingSpecs();

}  // namespace vroc::mujoco
