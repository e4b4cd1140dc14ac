// SPDX-License-Identifier: MIT
#include "dart_config.h"

#include <algorithm>
#include <cmath>

namespace vroc::dart {

std::vector<SettingSpec> dartSettingSpecs() {
    using T = SettingSpec::Type;
    return {
        {"dart.timestep",
         T::Real,
         "0.001",
         1e-6,
         1.0,
         {},
         "[s] largest internal step (DART World default 0.001); a frame is split into equal steps no longer than this"},
        {"dart.substeps",
         T::Integer,
         "0",
         0,
         1e6,
         {},
         "internal steps per frame, fixed (0: from dart.timestep). Set by --footing equal"},
        {"dart.max_substeps",
         T::Integer,
         "100000",
         1,
         1e9,
         {},
         "internal steps allowed per frame; a longer frame takes steps of dt / max_substeps"},
        {"dart.primitive_shapes",
         T::Choice,
         "primitive",
         0,
         0,
         {"mesh", "primitive"},
         "how FCL collides spheres and boxes: primitive = FCL's own sphere and box (DART 6.13's default); mesh = "
         "DART 6.12's default (a sphere is a 58-vertex polyhedron, a box 12 triangles: ~3 x the contact points)"},
        {"dart.friction_axes",
         T::Choice,
         "default",
         0,
         0,
         {"default", "sliding"},
         "first friction direction: DART's (world z on the contact plane, else normal x world x: fixed in the world), "
         "or along the "
         "virtual body's velocity, set before each step (the two-row friction box turns with the slide)"},
        {"dart.dantzig_max_rows",
         T::Integer,
         "300",
         0,
         1e9,
         {},
         "largest group of touching bodies [LCP rows] solved by DART's Dantzig solver (its default: pivoting, exact, "
         "O(rows^3)); larger groups by DART's projected Gauss-Seidel (30 iterations); 0: PGS everywhere"},
        {"dart.max_contacts",
         T::Integer,
         "0",
         0,
         1e7,
         {},
         "contact points collected per step over the whole world; 0: DART's 1000 to start with, doubled (the step "
         "taken again) whenever a step fills it; n > 0: fixed, a full step counted as contacts_dropped"},
    };
}

DartConfig DartConfig::from(const Settings& s) {
    DartConfig c;
    c.timestep = s.real("dart.timestep");
    c.substeps = static_cast<int>(s.integer("dart.substeps"));
    c.max_substeps = static_cast<int>(s.integer("dart.max_substeps"));
    c.primitive_shapes =
        s.text("dart.primitive_shapes") == "primitive" ? PrimitiveShapes::Primitive : PrimitiveShapes::Mesh;
    c.friction_axes = s.text("dart.friction_axes") == "sliding" ? FrictionAxes::Sliding : FrictionAxes::Default;
    c.dantzig_max_rows = static_cast<int>(s.integer("dart.dantzig_max_rows"));
    c.max_contacts = static_cast<int>(s.integer("dart.max_contacts"));
    return c;
}

// The tolerance keeps a dt that is a whole multiple of the timestep up to rounding (0.01 / 0.001)
// at 10, not 11 (as the MuJoCo backend does).
long DartConfig::stepsFor(double dt) const {
    if (substeps > 0) return substeps;
    return std::max(1L, static_cast<long>(std::ceil(dt / timestep - 1e-9)));
}

}  // namespace vroc::dart
