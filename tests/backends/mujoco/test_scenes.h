// SPDX-License-Identifier: MIT
// Scenes for the MuJoCo tests, built in code with closed-form mass properties.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "vroc/core/backend.h"
#include "vroc/core/scene.h"

namespace vroc::test {

/// Empty scene: gravity (0, 0, -9.81), frame dt 1/60 s, collision distance 1 mm, material "default".
Scene emptyScene(double restitution = 0.5, double friction = 0.5);
/// Adds a material, returns its index.
int addMaterial(Scene& scene, const std::string& name, double restitution, double friction);
/// Real box 20 x 20 x 1 m whose top face is the plane z = 0.
int addFloor(Scene& scene, int material = 0);
/// Virtual solid sphere [m, kg]: I = 2/5 m r^2.
int addBall(Scene& scene, const std::string& name, double radius, double mass, const Vec3& position, int material = 0);
/// Virtual solid box [half extents m, kg].
int addBox(Scene& scene, const std::string& name, const Vec3& half, double mass, const Vec3& position, int material = 0);
/// A cuboid as a hull (faces and planes by hand), vertices rotated by `rot` and shifted by `centre`
/// in the body frame: COM = centre, inertia R diag R^T.
ConvexPolyhedron cuboidHull(const Vec3& half, const Quat& rot = Quat::Identity(), const Vec3& centre = Vec3::Zero());
int addHullCuboid(Scene& scene, const std::string& name, const Vec3& half, double mass, const Pose& pose,
                  const Quat& rot_in_body = Quat::Identity(), const Vec3& centre_in_body = Vec3::Zero(),
                  int material = 0);
/// Solid cuboid inertia about its centre, in its own axes [kg m^2].
Mat3 cuboidInertia(const Vec3& half, double mass);

/// Creates the registered "mujoco" backend with `key=value` overrides.
std::unique_ptr<Backend> makeMujoco(const Scene& scene,
                                    const std::vector<std::pair<std::string, std::string>>& overrides = {});

/// Steps `frames` frames of the scene's frame dt.
void run(Backend& backend, const Scene& scene, int frames);

}  // namespace vroc::test
