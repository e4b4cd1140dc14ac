// SPDX-License-Identifier: MIT
// The ODE backend's `--set` keys and their parsed values. Every default is ODE's own where ODE
// has one (docs/ode-backend.md says where each comes from).
#pragma once

#include <vector>

#include "vroc/core/settings.h"

namespace vroc::ode {

enum class Stepper {
    QuickStep,   ///< dWorldQuickStep: projected Gauss-Seidel (SOR), O(constraints x iterations)
    Step,        ///< dWorldStep: Dantzig LCP, exact for the linearised step, O(constraints^3)
};

/// How a hull becomes an ODE geom (shape_mapping.h says why trimesh is the default).
enum class HullGeom {
    TriMesh,   ///< dCreateTriMesh of the triangulated faces (OPCODE colliders, several points per pair)
    Convex,    ///< dCreateConvex (libccd MPR in Debian's build: one point per pair)
};

/// The first friction axis of a contact (the second is normal x first).
enum class FrictionAxes {
    PlaneSpace,   ///< ODE's default: dPlaneSpace(normal), fixed in the world
    Sliding,      ///< dContactFDir1 along the relative tangential velocity at the step's start
};

/// Parsed `ode.*` settings.
struct OdeConfig {
    Stepper stepper = Stepper::QuickStep;
    int substeps = 1;                ///< world steps per frame (internal dt = frame dt / substeps)
    int quickstep_iterations = 20;   ///< dWorldSetQuickStepNumIterations (ODE default 20)
    double quickstep_w = 1.3;        ///< [-] dWorldSetQuickStepW, SOR over-relaxation (ODE default 1.3)
    double erp = 0.2;                ///< [-] dWorldSetERP (ODE default 0.2)
    double cfm = 1e-10;              ///< [-] dWorldSetCFM (ODE default 1e-10 in double precision)
    int max_contacts = 4;            ///< contact points asked of dCollide per geom pair
    HullGeom hull_geom = HullGeom::TriMesh;
    FrictionAxes friction_axes = FrictionAxes::PlaneSpace;
    double bounce_vel = 0.0;         ///< [m/s] dSurfaceParameters::bounce_vel: slower approaches do not bounce

    static OdeConfig from(const Settings& settings);
};

/// The declared keys, with types, ranges, defaults (those of OdeConfig) and help lines.
std::vector<SettingSpec> odeSettingSpecs();

}  // namespace vroc::ode
