// SPDX-License-Identifier: MIT
// Mechanical invariants of the virtual bodies, from BodyState and the scene's mass properties.
#pragma once

#include <span>
#include <vector>

#include "vroc/core/backend.h"
#include "vroc/core/scene.h"

namespace vroc::harness {

struct Invariants {
    double kinetic = 0;                    ///< [J] translational + rotational
    double potential = 0;                  ///< [J] -sum m g . x_com (zero at the world origin)
    Vec3 linear_momentum = Vec3::Zero();   ///< [kg m/s] world frame
    Vec3 angular_momentum = Vec3::Zero();  ///< [kg m^2/s] about the world origin, world frame
    double energy() const { return kinetic + potential; }   ///< [J]
};

/// Sums over the scene's virtual bodies; `states` is indexed like Scene::bodies.
Invariants computeInvariants(const Scene& scene, std::span<const BodyState> states);

/// Indices into Scene::bodies of the virtual (moving) bodies, in scene order.
std::vector<int> virtualBodyIndices(const Scene& scene);

/// [m] world position of a body's centre of mass.
Vec3 centerOfMass(const Body& body, const BodyState& state);

}  // namespace vroc::harness
