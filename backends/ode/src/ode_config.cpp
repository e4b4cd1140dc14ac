// SPDX-License-Identifier: MIT
#include "ode_config.h"

namespace vroc::ode {

std::vector<SettingSpec> odeSettingSpecs() {
    using T = SettingSpec::Type;
    return {
        {"ode.stepper", T::Choice, "quickstep", 0, 0, {"quickstep", "step"},
         "quickstep = dWorldQuickStep (iterative, O(n)); step = dWorldStep (Dantzig LCP, O(n^3))"},
        {"ode.substeps", T::Integer, "1", 1, 1000, {},
         "world steps per frame (internal dt = frame dt / substeps)"},
        {"ode.quickstep_iterations", T::Integer, "20", 1, 10000, {},
         "dWorldQuickStep iterations per step (ODE default 20)"},
        {"ode.quickstep_w", T::Real, "1.3", 0.01, 1.99, {},
         "[-] dWorldQuickStep successive over-relaxation factor (ODE default 1.3)"},
        {"ode.erp", T::Real, "0.2", 0.0, 1.0, {},
         "[-] error reduction parameter: share of a penetration corrected per step (ODE default 0.2)"},
        {"ode.cfm", T::Real, "1e-10", 0.0, 1.0, {},
         "[-] constraint force mixing: constraint softness (ODE default 1e-10 in double precision)"},
        {"ode.max_contacts", T::Integer, "4", 1, 64, {},
         "contact points asked of dCollide per geom pair (box-box keeps the best-spread ones)"},
        {"ode.hull_geom", T::Choice, "trimesh", 0, 0, {"trimesh", "convex"},
         "hull as dCreateTriMesh of its faces (OPCODE colliders) or dCreateConvex (libccd: one contact point)"},
        {"ode.friction_axes", T::Choice, "plane_space", 0, 0, {"plane_space", "sliding"},
         "first friction axis: ODE's dPlaneSpace(normal), or along the sliding velocity (dContactFDir1)"},
        {"ode.bounce_vel", T::Real, "0", 0.0, 100.0, {},
         "[m/s] approach speed at or below which a contact does not bounce (dContactBounce bounce_vel)"},
    };
}

OdeConfig OdeConfig::from(const Settings& s) {
    OdeConfig c;
    c.stepper = s.text("ode.stepper") == "step" ? Stepper::Step : Stepper::QuickStep;
    c.substeps = static_cast<int>(s.integer("ode.substeps"));
    c.quickstep_iterations = static_cast<int>(s.integer("ode.quickstep_iterations"));
    c.quickstep_w = s.real("ode.quickstep_w");
    c.erp = s.real("ode.erp");
    c.cfm = s.real("ode.cfm");
    c.max_contacts = static_cast<int>(s.integer("ode.max_contacts"));
    c.hull_geom = s.text("ode.hull_geom") == "convex" ? HullGeom::Convex : HullGeom::TriMesh;
    c.friction_axes = s.text("ode.friction_axes") == "sliding" ? FrictionAxes::Sliding : FrictionAxes::PlaneSpace;
    c.bounce_vel = s.real("ode.bounce_vel");
    return c;
}

}  // namespace vroc::ode
