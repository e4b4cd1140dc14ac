// SPDX-License-Identifier: MIT
// Scene -> MJCF text (MuJoCo's XML), in memory. Mapping (docs/mujoco-backend.md):
//  - a virtual body is a <body> with a free joint, placed at its centre of mass along its principal
//    axes (principal_frame.h), with the scene's mass and inertia in <inertial> (diaginertia);
//  - a real body is a <body> without joints (welded to the world, static);
//  - a tracked body is a <body> with a free joint at its own frame (its COM is the body origin),
//    trackedInertia() heavy, whose qpos and qvel the backend prescribes after every step (a mocap
//    body would be welded to the world: MuJoCo's contacts would not see its velocity);
//  - sphere and box parts are MuJoCo spheres and boxes, hull parts are meshes given by their
//    vertices (MuJoCo collides with the convex hull of a mesh's vertices), a compound is several
//    geoms on one body; geom poses are the parts' poses in the MuJoCo body frame;
//  - contacts: contype/conaffinity let virtual-virtual, virtual-real and virtual-tracked pairs
//    collide, never real-real, tracked-real or tracked-tracked (infinite mass on both sides);
//    materials as contact_materials.h says (geom values, or <exclude> + <pair>);
//  - margin = gap = the scene's collision distance: contacts that close are listed (for events)
//    but never enter the solver;
//  - with tracked bodies, <statistic meaninertia> of the virtual bodies alone (the solver's scale);
//  - <size nconmax njmax> grown with the virtual geoms (MuJoCo 2.2's default is 100 contacts);
//  - <option>: timestep, gravity and the solver settings (SolverOptions), always written out.
// Names: body i is "b<i>", part k of body i is geom "g<i>_<k>" (mesh "m<i>_<k>").
#pragma once

#include <string>

#include "contact_materials.h"
#include "vroc/core/scene.h"

namespace vroc::mujoco {

/// A tracked body's mass [kg] and isotropic moment of inertia [kg m^2] in MuJoCo: the heaviest
/// virtual body's mass (1 kg if none) times kTrackedMassRatio, and mass x (bounding radius)^2.
/// Isotropic, so a spinning tracked body has no gyroscopic torque.
struct TrackedInertia {
    double mass = 0.0;
    double inertia = 0.0;
};
constexpr double kTrackedMassRatio = 1e6;
TrackedInertia trackedInertia(const Scene& scene, const Body& body);

/// The <option> element's step and solver settings, in MJCF's words; the defaults are MuJoCo's.
struct SolverOptions {
    double timestep = 0.002;            ///< [s] (the backend sets the timestep per frame)
    std::string cone = "pyramidal";     ///< "pyramidal" or "elliptic"
    double impratio = 1.0;              ///< [-] friction-to-normal impedance ratio
    int noslip_iterations = 0;          ///< noslip post-solver iterations (0: off)
    std::string integrator = "Euler";   ///< "Euler", "RK4" or "implicit"
    /// [1/s] elliptic cone only: the friction rows' damping (direct solref form), written as the
    /// <numeric> friction_damping.h reads (0: not written, the friction rows keep the pair's damping)
    double friction_damping = 0.0;
    /// Phantom box-box contacts clamped to the boxes' overlap (box_depth_bound.h), written as a
    /// <numeric> with one mjData::userdata slot for the count (false: MuJoCo's contacts as they are)
    bool box_depth_bound = false;
};

/// MJCF for `scene` with `options` in its <option> element. Doubles are written with 17
/// significant digits, so they read back bit for bit.
std::string writeMjcf(const Scene& scene, const ContactMaterials& materials, const SolverOptions& options);

std::string bodyName(int body);
std::string geomName(int body, int part);

}  // namespace vroc::mujoco
