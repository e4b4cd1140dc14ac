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
    /// Friction rows per contact point: 1 (Bullet 3.24's default solver mode: one row along the
    /// sliding velocity) or 2 (SOLVER_USE_2_FRICTION_DIRECTIONS: a second row along dir1 x normal).
    int friction_directions = 1;
    /// [-] swept-sphere radius of continuous collision as a fraction of the body's inner radius
    /// (innerRadius(): the sphere fits inside the shape); Bullet has no default (CCD off).
    double ccd_radius = 0.5;

    static BulletConfig from(const Settings& settings);
};

/// The declared keys, with types, ranges, defaults (those of BulletConfig) and help lines.
std::vector<SettingSpec> bulletSettingSpecs();

}  // namespace vroc::bullet
