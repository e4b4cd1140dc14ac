// SPDX-License-Identifier: MIT
#include <ode/version.h>

#include <memory>
#include <string>

#include "ode_backend.h"
#include "ode_runtime.h"
#include "vroc/core/backend_registry.h"
#include "vroc/ode/ode_backend.h"

namespace vroc::ode {
namespace {

std::unique_ptr<Backend> create(const Scene& scene, const Settings& settings) {
    return std::make_unique<OdeBackend>(scene, OdeConfig::from(settings));
}

BackendCapabilities capabilities() {
    BackendCapabilities c;
    c.sphere = Support::Exact;
    c.box = Support::Exact;
    c.hull = Support::Approximated;
    c.compound = Support::Exact;
    c.restitution = Support::Approximated;
    c.tracked = Support::Exact;   // dBodySetKinematic: infinite mass, its velocity in the contact rows
    c.friction = FrictionModel::Pyramid;
    c.continuous_collision = false;
    c.deterministic = true;
    c.precision = "double";
    c.notes["hull"] = "an ODE trimesh of the triangulated faces (the same surface; OPCODE colliders): a surface, "
                      "not a solid, so a body wholly inside it feels nothing (ode.hull_geom=convex: dCreateConvex, "
                      "one libccd contact point per pair, rocks and topples)";
    c.notes["restitution"] = "dContactBounce: separating speed >= e x the approach speed at the start of the step "
                             "that first finds the overlap; the overlap (up to v h) is not undone first";
    c.notes["friction"] = "dContactApprox1: two friction rows per contact point along dPlaneSpace(normal) axes, "
                          "each clamped to mu x normal force (up to sqrt(2) mu N sliding diagonally; "
                          "ode.friction_axes=sliding aligns the first axis with the sliding velocity)";
    c.notes["continuous_collision"] = "none: ODE collides poses at step starts only";
    return c;
}

// Equal footing: `substeps` world steps a frame, and the first friction axis along the slip
// (ode.friction_axes=sliding) so that the two-row friction pyramid turns with the motion: a
// diagonal slide keeps its heading and its Coulomb distance (docs/ode-backend.md).
std::vector<std::pair<std::string, std::string>> equalFooting(int substeps) {
    return {{"ode.substeps", std::to_string(substeps)}, {"ode.friction_axes", "sliding"}};
}

}  // namespace

void registerBackend() {
    if (BackendRegistry::global().find("ode")) return;   // calling twice is harmless
    BackendInfo info;
    info.name = "ode";
    info.description = "reference: Open Dynamics Engine 0.16, double precision, dWorldQuickStep, one step per frame, no sleeping";
    info.version = std::string("ODE ") + dODE_VERSION + " (double)";
    info.capabilities = capabilities();
    info.deviations = {
        "material rule: restitution = min (dContactBounce, bounce_vel 0 m/s), friction = geometric mean with "
        "dContactApprox1 (friction <= mu x normal force); ODE has no material rule of its own, and without "
        "dContactApprox1 its mu is a force bound in newtons",
        "hulls as dCreateTriMesh (ode.hull_geom=trimesh), not dCreateConvex: Debian's ODE collides convex geoms "
        "with libccd's MPR, one contact point per pair, and a resting hull cube topples (docs/ode-backend.md)",
        "QuickStep's random constraint order: each backend keeps its own state of ODE's process-wide dRand "
        "generator, so a run's bits do not depend on other ODE worlds in the process",
        "step rate: one world step per frame (ode.substeps = 1); ODE has no step size of its own, the caller "
        "picks it, and one step per frame is how a game or a simulator drives it",
        "contacts per geom pair: at most ode.max_contacts = 4 asked of dCollide (ODE has no default: the caller "
        "passes the room; box-box can report up to 8)",
    };
    info.settings = odeSettingSpecs();
    info.create = &create;
    info.equal_footing = &equalFooting;
    BackendRegistry::global().add(std::move(info));
}

}  // namespace vroc::ode
