// SPDX-License-Identifier: MIT
#include <dart/config.hpp>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "dart_backend.h"
#include "vroc/core/backend_registry.h"
#include "vroc/dart/dart_backend.h"

namespace vroc::dart {
namespace {

std::unique_ptr<Backend> create(const Scene& scene, const Settings& settings) {
    return std::make_unique<DartBackend>(scene, DartConfig::from(settings));
}

BackendCapabilities capabilities() {
    BackendCapabilities c;
    c.sphere = Support::Exact;  // FCL's own sphere and box (dart.primitive_shapes=primitive, the default)
    c.box = Support::Exact;
    c.hull = Support::Approximated;
    c.compound = Support::Exact;
    c.restitution = Support::Approximated;
    c.tracked = Support::Exact;  // VELOCITY-actuated FreeJoint: not reactive, its velocity in the contact rows
    c.friction = FrictionModel::Pyramid;
    c.continuous_collision = false;
    c.deterministic = true;
    c.precision = "double";
    c.notes["hull"] =
        "a MeshShape of the triangulated faces (DART 6.12 has no convex-polyhedron shape), collided by "
        "FCL as a triangle surface, not a solid: a body wholly inside it feels nothing; vertices in "
        "single precision (assimp's ai_real)";
    c.notes["restitution"] =
        "ContactConstraint bounces a contact only when e x its approach speed exceeds 0.1 m/s "
        "(DART_BOUNCING_VELOCITY_THRESHOLD), capped at 100 m/s, at the step that first finds "
        "the overlap (not undone first)";
    c.notes["friction"] =
        "a boxed LCP with two friction rows per contact point, each clamped to mu x the normal "
        "impulse (a 4-sided pyramid: up to sqrt(2) mu N sliding diagonally); the first row along "
        "world z projected on the contact plane, else normal x world x; dart.friction_axes=sliding "
        "turns it along each virtual body's velocity";
    c.notes["continuous_collision"] = "none: DART collides poses at step starts only";
    return c;
}

// Under dart.primitive_shapes=mesh (DART 6.12's own default) FCL collides spheres and boxes as meshes.
BackendCapabilities capabilitiesWith(const Settings& settings) {
    BackendCapabilities c = capabilities();
    const auto shapes = settings.values().find("dart.primitive_shapes");
    if (shapes == settings.values().end() || shapes->second != "mesh") return c;
    c.sphere = Support::Approximated;
    c.box = Support::Approximated;
    c.notes["sphere"] =
        "dart.primitive_shapes=mesh (DART 6.12's default): FCL collides a 58-vertex polyhedron "
        "inscribed in the sphere, so a ball rests and rolls on facets";
    c.notes["box"] = "dart.primitive_shapes=mesh: collided as a 12-triangle surface, contacts from triangle pairs";
    return c;
}

// Equal footing: `substeps` world steps a frame, and the first friction row along the slide
// (dart.friction_axes=sliding) so that the two-row friction box turns with the motion.
std::vector<std::pair<std::string, std::string>> equalFooting(int substeps) {
    return {{"dart.substeps", std::to_string(substeps)}, {"dart.friction_axes", "sliding"}};
}

}  // namespace

void registerBackend() {
    if (BackendRegistry::global().find("dart")) return;  // calling twice is harmless
    BackendInfo info;
    info.name = "dart";
    info.description = "reference: DART 6.12, FCL primitives, boxed LCP (Dantzig; PGS for piles), 1 ms steps";
    info.version = std::string("DART ") + DART_VERSION + " (double, FCL)";
    info.capabilities = capabilities();
    info.deviations = {
        "material rule: restitution = min, friction = geometric mean (the scene's rule), fed to DART's own rule "
        "(friction = min, restitution = product of the two shape nodes) through one shape-node set per material "
        "class a body may touch and a collision filter that pairs them (docs/dart-backend.md)",
        "step rate: a frame is split into equal steps no longer than dart.timestep = 0.001 s (DART's World "
        "default), so a 1/60 s frame takes 17 steps of 0.98 ms; DART leaves the frame to the caller",
        "contact buffer: DART collects at most 1000 contact points per step and silently drops the rest; here a "
        "step that fills it is taken again with twice the room (dart.max_contacts = 0), so no contact is dropped",
        "collision filter: DART's BodyNodeCollisionFilter replaced by the material-class filter, which also skips "
        "pairs with no virtual body (DART collides them, then finds no reactive body to solve)",
        "FCL primitives (dart.primitive_shapes=primitive; DART 6.13's default): DART 6.12's ConstraintSolver has FCL "
        "collide spheres and boxes as meshes (a ball a 58-vertex polyhedron); on a 56-box pyramid that gives 1,100 "
        "contact points per step instead of 400 and 6 s per step instead of 0.16 s; except in a scene with both "
        "spheres "
        "and hulls, which keeps the meshes: FCL's own sphere misses a hull's triangle mesh (a ball falls through a "
        "static hull, and the staircase's balls through every step; statistic dart.mesh_collision_for_hulls)",
        "LCP solver: groups of touching bodies above dart.dantzig_max_rows = 300 rows are solved by DART's PGS, not "
        "its default Dantzig solver: DART builds one dense LCP per group and Dantzig is O(rows^3) (a pile of boxes "
        "would take seconds to minutes per step); smaller groups (every check scene) keep Dantzig",
    };
    info.settings = dartSettingSpecs();
    info.create = &create;
    info.equal_footing = &equalFooting;
    info.capabilities_with = &capabilitiesWith;
    BackendRegistry::global().add(std::move(info));
}

}  // namespace vroc::dart
