// SPDX-License-Identifier: MIT
// Building scenes in code for the analytic checks: materials and bodies with exact mass properties.
#pragma once

#include <string>

#include "vroc/core/scene.h"

namespace vroc::harness {

/// An empty scene with the given gravity [m/s^2] and frame step [s].
Scene emptyScene(const std::string& name, const Vec3& gravity, double frame_dt);
/// Adds a material (restitution, friction) and returns its index.
int addMaterial(Scene& scene, double restitution, double friction);
/// Adds a body; mass [kg] 0 makes it real (static). Returns its index.
int addBody(Scene& scene, const std::string& name, Shape shape, double mass, const Pose& pose, int material,
            const Vec3& velocity = Vec3::Zero(), const Vec3& angular_velocity = Vec3::Zero());
/// A static ground box whose top face is the plane z = 0, half extents (hx, hy, 0.5) m.
/// Adds a tracked body: infinite mass, moving at `velocity` [m/s] and `angular_velocity` [rad/s].
int addTracked(Scene& scene, const std::string& name, Shape shape, const Pose& pose, int material,
               const Vec3& velocity, const Vec3& angular_velocity = Vec3::Zero());
int addGround(Scene& scene, double hx, double hy, int material);
/// Pose at a position with identity orientation.
Pose at(const Vec3& position);

}  // namespace vroc::harness
