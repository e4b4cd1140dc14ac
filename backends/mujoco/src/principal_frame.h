// SPDX-License-Identifier: MIT
// A MuJoCo body here is placed at the scene body's centre of mass with the principal axes of
// inertia, so the free joint's linear velocity is the COM velocity and <inertial> is diagonal.
// This finds that frame relative to the scene's body frame.
#pragma once

#include "vroc/core/mass_properties.h"
#include "vroc/core/math.h"

namespace vroc::mujoco {

struct PrincipalFrame {
    Pose com_in_body;                          ///< principal frame -> scene body frame:
                                               ///< position = COM [m], orientation = principal axes
    Vec3 principal_inertia = Vec3::Zero();     ///< [kg m^2] diagonal inertia in the principal frame
};

/// Diagonalises the inertia about the COM with a proper rotation (det = +1). An inertia that is
/// already diagonal (to round-off) keeps the body axes exactly, so simple bodies get no rotation.
PrincipalFrame principalFrame(const MassProperties& props);

}  // namespace vroc::mujoco
