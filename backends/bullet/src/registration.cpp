// SPDX-License-Identifier: MIT
#include <LinearMath/btScalar.h>

#include <string>
#include <utility>
#include <vector>

#include "bullet_backend.h"
#include "vroc/bullet/bullet_backend.h"
#include "vroc/core/backend_registry.h"

static_assert(sizeof(btScalar) == 8, "the Bullet backend needs Bullet in double precision (bullet-float64)");

namespace vroc::bullet {
namespace {

std::unique_ptr<Backend> create(const Scene& scene, const Settings& settings) {
    return std::make_unique<BulletBackend>(scene, BulletConfig::from(settings));
}

std::string versionText() {
    return "Bullet " + std::to_string(BT_BULLET_VERSION / 100) + "." + std::to_string(BT_BULLET_VERSION % 100) +
           " (double)";
}

// Equal footing: `substeps` fixed internal steps a frame. Bullet's default friction (one row along
// the slip) already keeps a slide's heading: nothing else to set.
std::vector<std::pair<std::string, std::string>> equalFooting(int substeps) {
    return {{"bullet.substeps", std::to_string(substeps)}};
}

}  // namespace

void registerBackend() {
    if (BackendRegistry::global().find("bullet")) return;   // calling twice is harmless
    BackendInfo info;
    info.name = "bullet";
    info.description = "reference: Bullet btDiscreteDynamicsWorld, double precision, fixed sub-steps, no sleeping";
    info.version = versionText();
    BackendCapabilities& c = info.capabilities;
    c.sphere = Support::Exact;
    c.box = Support::Approximated;
    c.hull = Support::Approximated;
    c.compound = Support::Exact;
    c.restitution = Support::Approximated;
    c.tracked = Support::Exact;   // kinematic bodies: infinite mass, their velocity in the contact solve
    c.friction = FrictionModel::Cone;   // one row along the slip (see the note), not a pyramid
    c.continuous_collision = true;
    c.deterministic = true;
    c.precision = "double";
    c.notes["box"] = "edges and corners rounded by the collision margin (bullet.margin, 0.04 m by default)";
    c.notes["hull"] = "faces shrunk by the margin so the rounded surface lies on the scene's faces; edges and "
                      "corners rounded by it";
    c.notes["restitution"] = "approach speeds below bullet.restitution_threshold (0.2 m/s) bounce with e = 0";
    c.notes["friction"] =
        "one friction row per contact point, along the sliding velocity, clamped to mu x normal impulse "
        "(Bullet 3.24's default solver mode, warm starting + SIMD, without "
        "SOLVER_USE_2_FRICTION_DIRECTIONS): a sliding point meets Coulomb's circular cone; a point "
        "that does not slide gets one row along btPlaneSpace1's first axis; bullet.friction_directions=2 "
        "adds Bullet's second row across the slip (SOLVER_USE_2_FRICTION_DIRECTIONS)";
    c.notes["continuous_collision"] =
        "swept sphere of bullet.ccd_radius (0.5) x the inner radius (Bullet's CCD), not exact time of impact: "
        "a fast body is stopped with its centre that radius before the surface it would have crossed";
    info.deviations = {
        "double precision (bullet-float64): every backend solves in double",
        "sleeping off (DISABLE_DEACTIVATION): comparisons keep every body awake on every backend",
        "material rule: restitution = min, friction = geometric mean (the scene's rule; Bullet multiplies both)",
        "swept-sphere CCD on for virtual bodies (Bullet: off): the scenes throw fast bodies at thin walls; "
        "the swept sphere's radius is bullet.ccd_radius (default 0.5) of the body's inner radius and the motion "
        "threshold the inner radius (Bullet has no default for either: CCD is off)",
        "box margin: bullet.margin, but at most a quarter of the box's smallest half extent, so a thin plate keeps "
        "a flat face (Bullet's own default margin is 0.04 m whatever the box)",
        "hull faces shrunk by the margin (bullet.shrink_hulls): surfaces where the scene puts them",
    };
    info.settings = bulletSettingSpecs();
    info.create = &create;
    info.equal_footing = &equalFooting;
    BackendRegistry::global().add(std::move(info));
}

}  // namespace vroc::bullet
