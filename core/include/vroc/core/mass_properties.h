// SPDX-License-Identifier: MIT
// Exact mass properties at uniform density (polyhedra by the divergence theorem, no sampling).
#pragma once

#include "vroc/core/math.h"
#include "vroc/core/shape.h"

namespace vroc {

struct MassProperties {
    double mass = 0.0;                    ///< [kg]
    double volume = 0.0;                  ///< [m^3]
    Vec3 center_of_mass = Vec3::Zero();   ///< [m] in the body frame
    Mat3 inertia = Mat3::Zero();          ///< [kg m^2] about the centre of mass, body-frame axes
};

/// Volume [m^3], centroid [m] and unit-density inertia about the centroid, in the shape's frame.
/// Compound parts are summed (overlaps counted twice: parts are expected not to overlap).
MassProperties unitDensityProperties(const Shape& shape);

/// Properties for a body of the given total mass [kg] at uniform density.
MassProperties massProperties(const Shape& shape, double mass);

}  // namespace vroc
