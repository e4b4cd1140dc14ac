// SPDX-License-Identifier: MIT
#include "bullet_config.h"

namespace vroc::bullet {

std::vector<SettingSpec> bulletSettingSpecs() {
    using T = SettingSpec::Type;
    return {
        {"bullet.substeps", T::Integer, "1", 1, 1000, {},
         "fixed internal steps per frame (internal dt = frame dt / substeps); Bullet's own default is 1 "
         "per 1/60 s frame, 4 is the sweeps' accurate setting"},
        {"bullet.solver_iterations", T::Integer, "10", 1, 1000, {},
         "sequential-impulse solver iterations per internal step (Bullet default 10)"},
        {"bullet.ccd", T::Boolean, "true", 0, 0, {},
         "swept-sphere continuous collision detection on virtual bodies"},
        {"bullet.margin", T::Real, "0.04", 0.0, 0.1, {},
         "[m] collision margin of boxes and hulls (Bullet default 0.04; clamped for thin shapes)"},
        {"bullet.shrink_hulls", T::Boolean, "true", 0, 0, {},
         "shrink hull faces inward by the margin so the rounded surface lies on the scene's faces"},
        {"bullet.split_impulse", T::Boolean, "true", 0, 0, {},
         "split-impulse penetration recovery (Bullet default on)"},
        {"bullet.restitution_threshold", T::Real, "0.2", 0.0, 100.0, {},
         "[m/s] approach speed below which Bullet zeroes restitution (Bullet default 0.2)"},
        {"bullet.warmstarting_factor", T::Real, "0.85", 0.0, 1.0, {},
         "[-] fraction of the previous step's contact impulse the solver starts from (Bullet 0.85)"},
        {"bullet.friction_directions", T::Integer, "1", 1, 2, {},
         "friction rows per contact point: 1 = Bullet 3.24's default, one row along the slip; 2 = "
         "SOLVER_USE_2_FRICTION_DIRECTIONS, a second row across it"},
        {"bullet.ccd_radius", T::Real, "0.5", 0.01, 1.0, {},
         "[-] CCD swept-sphere radius as a fraction of the body's inner radius (Bullet has no default: CCD is off)"},
    };
}

BulletConfig BulletConfig::from(const Settings& s) {
    BulletConfig c;
    c.substeps = static_cast<int>(s.integer("bullet.substeps"));
    c.solver_iterations = static_cast<int>(s.integer("bullet.solver_iterations"));
    c.ccd = s.boolean("bullet.ccd");
    c.margin = s.real("bullet.margin");
    c.shrink_hulls = s.boolean("bullet.shrink_hulls");
    c.split_impulse = s.boolean("bullet.split_impulse");
    c.restitution_threshold = s.real("bullet.restitution_threshold");
    c.warmstarting_factor = s.real("bullet.warmstarting_factor");
    c.friction_directions = static_cast<int>(s.integer("bullet.friction_directions"));
    c.ccd_radius = s.real("bullet.ccd_radius");
    return c;
}

}  // namespace vroc::bullet
