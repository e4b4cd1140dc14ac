// SPDX-License-Identifier: MIT
#include <mujoco/mujoco.h>

#include <string>
#include <utility>
#include <vector>

#include "mujoco_backend.h"
#include "mujoco_config.h"
#include "vroc/core/backend_registry.h"
#include "vroc/mujoco/mujoco_backend.h"

static_assert(sizeof(mjtNum) == 8, "the MuJoCo backend needs MuJoCo in double precision");

namespace vroc::mujoco {
namespace {

std::unique_ptr<Backend> create(const Scene& scene, const Settings& settings) {
    return std::make_unique<MujocoBackend>(scene, MujocoConfig::from(settings));
}

BackendCapabilities capabilities() {
    BackendCapabilities c;
    c.sphere = Support::Exact;
    c.box = Support::Exact;
    c.hull = Support::Approximated;
    c.compound = Support::Exact;
    c.restitution = Support::Approximated;
    c.tracked = Support::Approximated;
    c.friction = FrictionModel::Pyramid;
    c.continuous_collision = false;
    c.deterministic = true;
    c.precision = "double";
    c.notes["restitution"] =
        "MuJoCo has no restitution: each pair's e sets the damping ratio of its soft-contact spring "
        "(solref -K -B, K = 1/tc^2, tc = mujoco.contact_timeconst), inverting a spring-damper released at "
        "zero force; 1 m ball drop: first apex within 3 % of e^2 h (e = 0.5 and 1), slower impacts lose more "
        "(e = 0.5: second and third apex about -14 %); e below ~0.1 is floored by the damping cap";
    c.notes["tracked"] =
        "a free body 1e6 x heavier than the heaviest virtual body (not infinite), its weight cancelled and its qpos "
        "and qvel set from the tracker after every step: contacts see its velocity (a mocap body's they would not), "
        "a struck body recoils as from that mass (relative error ~1e-6) through the soft contact of the "
        "restitution note";
    c.notes["friction"] =
        "MuJoCo's default pyramidal cone (4 edges): mu along the contact frame's tangents, mu / sqrt2 along their "
        "diagonals (a box slid along the diagonal goes sqrt2 as far); --set mujoco.cone=elliptic gives Coulomb's "
        "circular cone (heading kept, stop distance within 0.3 % of v^2 / (2 mu g))";
    c.notes["hull"] =
        "the hull is exact (a MuJoCo mesh of its vertices, stored as floats), but MuJoCo 2.2 gives one contact "
        "point per mesh pair (MPR): a hull resting on a face rocks and sinks up to ~0.5 mm";
    return c;
}

// Under mujoco.cone=elliptic the friction law is Coulomb's circular cone (MuJoCo's elliptic cone).
BackendCapabilities capabilitiesWith(const Settings& settings) {
    BackendCapabilities c = capabilities();
    const auto cone = settings.values().find("mujoco.cone");
    if (cone != settings.values().end() && cone->second == "elliptic") {
        c.friction = FrictionModel::Cone;
        c.notes.erase("friction");
    }
    return c;
}

// Equal footing: `substeps` internal steps a frame (mujoco.substeps: the restitution mapping made for
// that step, the contact spring no faster than two of them) and Coulomb's circular cone
// (mujoco.cone=elliptic: a diagonal slide keeps its heading and its Coulomb distance).
std::vector<std::pair<std::string, std::string>> equalFooting(int substeps) {
    return {{"mujoco.substeps", std::to_string(substeps)}, {"mujoco.cone", "elliptic"}};
}

}  // namespace

void registerBackend() {
    if (BackendRegistry::global().find("mujoco")) return;   // calling twice is harmless
    BackendInfo info;
    info.name = "mujoco";
    info.description =
        "reference: MuJoCo 2.2 soft-contact solver (Newton, pyramidal cone, Euler by default), double precision";
    info.version = std::string("MuJoCo ") + mj_versionString() + " (double)";
    info.capabilities = capabilities();
    info.deviations = {
        "timestep: each frame is n = ceil(dt / mujoco.timestep) equal steps (1/60 s frames: 9 steps of 1.852 ms, "
        "not MuJoCo's 2 ms) so that every frame ends on a step",
        "restitution: each pair's solref is the direct form (-K, -B) with K = 1/tc^2 (tc = mujoco.contact_timeconst, "
        "default 6 ms) and a damping ratio mapped from e = min(ea, eb) (MuJoCo default solref (0.02 s, 1) has no "
        "restitution)",
        "friction: sqrt(mu_a mu_b) per pair, the scene's rule (MuJoCo mixes geoms by the larger friction): pairs "
        "whose materials differ are explicit <pair>s excluded from the broad phase",
        "contact margin = gap = the scene's collision_distance (MuJoCo default 0): contacts that close are listed "
        "for collision events but never enter the solver",
        "mass and inertia: the scene's, in <inertial> (inertiafromgeom false), bodies placed at their centre of "
        "mass along the principal axes",
        "messages: warnings are counted, not printed; an error (mju_error) is caught instead of ending the process",
        "buffer sizes: from the scene, nconmax = max(100, 8 x virtual geoms), njmax = max(500, 4 x nconmax) up to "
        "256 MB of constraint arrays, nstack 1e6 + 2000 (nv + njmax) (MuJoCo's default room of 100 contacts overflows on any box stack); "
        "a step that overflows one is taken again with it doubled (rows up to 1 GB of arrays; mujoco.buffer_growths)",
        "solver scale in scenes with tracked bodies: <statistic meaninertia> of the virtual bodies alone, so the "
        "tracked bodies' 1e6 masses (see the tracked note) do not loosen the solver's tolerance",
        "elliptic cone only (mujoco.cone=elliptic with mujoco.restitution=solref): the friction rows' damping is the "
        "one the restitution mapping gives e = 0, whatever the pair's e (MuJoCo 2.2 damps friction with the "
        "contact's solref, so the mapping would weaken friction as e grows and remove it at e = 1)",
        "box-box contacts deeper than the two boxes' overlap along their normal are clamped to it, only with "
        "mujoco.bound_box_depth=true (off by default): MuJoCo 2.2's box-box collider returns phantom contacts about a "
        "box width deep for boxes resting face to face (upstream issue #3476), which throw stacks apart",
    };
    info.settings = mujocoSettingSpecs();
    info.create = &create;
    info.equal_footing = &equalFooting;
    info.capabilities_with = &capabilitiesWith;
    BackendRegistry::global().add(std::move(info));
}

}  // namespace vroc::mujoco
