// SPDX-License-Identifier: MIT
// The Bullet backend's `--set` keys and their parsed values.
#pragma once

#include <vector>

#include "vroc/core/settings.h"

namespace vroc::bullet {

/// Parsed `bullet.*` settings (docs/bullet-backend.md explains each default).
struct BulletConfig {
    int substeps = 1;                        ///< fixed internal steps per frame (Bullet's own default: 1 per 1/60 s)
    int solver_iterations = 10;              ///< sequential-impulse iterations per internal step
    bool ccd = true;                         ///< swept-sphere CCD on virtual bodies
    double margin = 0.04;                    ///< [m] collision margin of boxes and hulls
    bool shrink_hulls = true;                ///< hulls shrunk by the margin so faces stay in place
    bool split_impulse = true;               ///< Bullet's split-impulse position correction
    double restitution_threshold = 0.2;      ///< [m/s] below this approach speed restitution is 0
    double warmstarting_factor = 0.85;       ///< [-] fraction of last step's impulse reused

    static BulletConfig from(const Settings& settings);
};

/// The declared keys, with types, ranges, defaults (those of BulletConfig) and help lines.
std::vector<SettingSpec> bulletSettingSpecs();

}  // namespace vroc::bullet
