// SPDX-License-Identifier: MIT
// The DART backend's `--set` keys and their parsed values. Every default is DART 6.12's own where
// DART has one (docs/dart-backend.md says where each comes from).
#pragma once

#include <vector>

#include "vroc/core/settings.h"

namespace vroc::dart {

/// How FCL sees spheres and boxes (FCLCollisionDetector::PrimitiveShape).
enum class PrimitiveShapes {
    Mesh,       ///< DART 6.12's default: a sphere is a 58-vertex polyhedron, a box 12 triangles
    Primitive,  ///< FCL's own sphere and box (DART 6.13's default; the default here, docs/dart-backend.md)
};

/// The first friction direction of a contact (the second is normal x first).
enum class FrictionAxes {
    Default,  ///< DART's: world z projected on the contact plane, else normal x world x
    Sliding,  ///< along the virtual body's centre-of-mass velocity, set before each step
};

/// Parsed `dart.*` settings.
struct DartConfig {
    double timestep = 0.001;    ///< [s] largest internal step (DART's World default 0.001 s)
    int substeps = 0;           ///< internal steps per frame, fixed (0: from timestep)
    int max_substeps = 100000;  ///< internal steps allowed per frame
    PrimitiveShapes primitive_shapes = PrimitiveShapes::Primitive;
    FrictionAxes friction_axes = FrictionAxes::Default;
    /// Largest group of touching bodies [LCP rows] solved by DART's Dantzig solver (its default);
    /// larger groups by DART's PGS (sized_lcp_solver.h says why). 0: PGS for every group.
    int dantzig_max_rows = 300;
    /// CollisionOption::maxNumContacts per step, whole world; 0: start at DART's 1000 and double it (the
    /// step taken again) whenever a step fills it, so no contact is dropped for want of room
    int max_contacts = 0;

    static DartConfig from(const Settings& settings);
    /// Internal steps for a frame of `dt` [s]: `substeps` if set, else the fewest no longer than `timestep`.
    long stepsFor(double dt) const;
};

/// The declared keys, with types, ranges, defaults (those of DartConfig) and help lines.
std::vector<SettingSpec> dartSettingSpecs();

}  // namespace vroc::dart
