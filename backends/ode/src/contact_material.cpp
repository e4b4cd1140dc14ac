// SPDX-License-Identifier: MIT
#include "contact_material.h"

namespace vroc::ode {

dSurfaceParameters surfaceFor(const Material& a, const Material& b, double bounce_vel) {
    const ContactMaterial m = combineMaterials(a, b);
    dSurfaceParameters s{};
    s.mode = dContactApprox1;
    s.mu = m.friction;
    if (m.restitution > 0.0) {
        s.mode |= dContactBounce;
        s.bounce = m.restitution;
        s.bounce_vel = bounce_vel;
    }
    return s;
}

}  // namespace vroc::ode
