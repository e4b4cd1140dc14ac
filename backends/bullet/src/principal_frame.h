// SPDX-License-Identifier: MIT
// Bullet puts a rigid body's frame at its centre of mass with the principal axes of inertia.
// This finds that frame relative to the scene's body frame.
#pragma once

#include "vroc/core/mass_properties.h"
#include "vroc/core/math.h"

namespace vroc::bullet {

struct PrincipalFrame {
    Pose body_to_com;                     ///< principal (COM) frame -> scene body frame:
                                          ///< position = COM [m], orientation = principal axes
    Vec3 principal_inertia = Vec3::Zero();   ///< [kg m^2] diagonal inertia in the principal frame
};

/// Diagonalises the inertia about the COM (a proper rotation, det = +1). An inertia that is
/// already diagonal keeps the body axes exactly, so simple bodies need no compound wrapper.
PrincipalFrame principalFrame(const MassProperties& props);

}  // namespace vroc::bullet
