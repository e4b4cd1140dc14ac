// SPDX-License-Identifier: MIT
// Scene -> MJCF text (MuJoCo's XML), in memory. Mapping (docs/mujoco-backend.md):
//  - a virtual body is a <body> with a free joint, placed at its centre of mass along its principal
//    axes (principal_frame.h), with the scene's mass and inertia in <inertial> (diaginertia);
//  - a real body is a <body> without joints (welded to the world, static);
//  - sphere and box parts are MuJoCo spheres and boxes, hull parts are meshes given by their
//    vertices (MuJoCo collides with the convex hull of a mesh's vertices), a compound is several
//    geoms on one body; geom poses are the parts' poses in the MuJoCo body frame;
//  - contacts: contype/conaffinity let virtual-virtual and virtual-real pairs collide, never
//    real-real; materials as contact_materials.h says (geom values, or <exclude> + <pair>);
//  - margin = gap = the scene's collision distance: contacts that close are listed (for events)
//    but never enter the solver;
//  - <size nconmax njmax> grown with the virtual geoms (MuJoCo 2.2's default is 100 contacts).
// Names: body i is "b<i>", part k of body i is geom "g<i>_<k>" (mesh "m<i>_<k>").
#pragma once

#include <string>

#include "contact_materials.h"
#include "vroc/core/scene.h"

namespace vroc::mujoco {

/// MJCF for `scene` with option timestep `timestep` [s] (the backend sets the timestep per frame).
/// Doubles are written with 17 significant digits, so they read back bit for bit.
std::string writeMjcf(const Scene& scene, const ContactMaterials& materials, double timestep);

std::string bodyName(int body);
std::string geomName(int body, int part);

}  // namespace vroc::mujoco
