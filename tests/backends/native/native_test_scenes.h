// SPDX-License-Identifier: MIT
// Scenes built in code for the native dynamics tests (closed-form answers need exact set-ups).
#pragma once

#include <cmath>
#include <memory>
#include <random>
#include <string>

#include "backend/native_backend.h"
#include "dynamics/rigid_body.h"
#include "vroc/core/mass_properties.h"
#include "vroc/core/scene.h"

namespace vroc::native::test {

inline Scene emptyScene(double collision_distance = 1e-3, Vec3 gravity = Vec3(0, 0, -9.81)) {
    Scene s;
    s.name = "test";
    s.gravity = gravity;
    s.collision_distance = collision_distance;
    return s;
}

inline int addMaterial(Scene& s, double restitution, double friction) {
    Material m;
    m.name = "m" + std::to_string(s.materials.size());   // GCC 12 may warn -Wrestrict here: a known false positive
    m.restitution = restitution;
    m.friction = friction;
    s.materials.push_back(std::move(m));
    return static_cast<int>(s.materials.size()) - 1;
}

/// Adds a body; virtual bodies get uniform-density mass properties of `mass` [kg].
inline int addBody(Scene& s, const std::string& name, Shape shape, const Pose& pose, int material,
                   bool is_static, double mass = 1.0) {
    Body b;
    b.name = name;
    b.role = is_static ? BodyRole::Real : BodyRole::Virtual;
    b.material = material;
    b.shape = std::move(shape);
    b.pose = pose;
    if (!is_static) b.mass_properties = massProperties(b.shape, mass);
    s.bodies.push_back(std::move(b));
    return static_cast<int>(s.bodies.size()) - 1;
}

/// Adds a tracked body (infinite mass, moving at `velocity` [m/s] and `angular_velocity` [rad/s]).
inline int addTracked(Scene& s, const std::string& name, Shape shape, const Pose& pose, int material,
                      const Vec3& velocity, const Vec3& angular_velocity = Vec3::Zero()) {
    Body b;
    b.name = name;
    b.role = BodyRole::Tracked;
    b.material = material;
    b.shape = std::move(shape);
    b.pose = pose;
    b.linear_velocity = velocity;
    b.angular_velocity = angular_velocity;
    s.bodies.push_back(std::move(b));
    return static_cast<int>(s.bodies.size()) - 1;
}
inline Pose at(const Vec3& p, const Quat& q = Quat::Identity()) {
    Pose pose;
    pose.position = p;
    pose.orientation = q;
    return pose;
}

/// A box of random size, mass, pose and velocity within a few metres of the origin.
inline RigidBody randomBody(std::mt19937_64& rng, bool is_static = false) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Body b;
    b.name = "b";
    b.role = is_static ? BodyRole::Real : BodyRole::Virtual;
    b.shape = Shape::box(Vec3(0.1 + 0.5 * std::abs(u(rng)), 0.1 + 0.5 * std::abs(u(rng)),
                              0.1 + 0.5 * std::abs(u(rng))));
    if (!is_static) b.mass_properties = massProperties(b.shape, 0.5 + 5 * std::abs(u(rng)));
    b.pose = at(Vec3(u(rng), u(rng), u(rng)) * 3,
                Quat(Eigen::AngleAxisd(3 * u(rng), Vec3(u(rng), u(rng), u(rng)).normalized())));
    b.linear_velocity = Vec3(u(rng), u(rng), u(rng)) * 4;
    b.angular_velocity = Vec3(u(rng), u(rng), u(rng)) * 3;
    return RigidBody::fromScene(b);
}

/// A static floor box whose top face is the plane z = 0.
inline int addFloor(Scene& s, int material, double half_size = 20.0) {
    return addBody(s, "floor", Shape::box(Vec3(half_size, half_size, 0.5)), at(Vec3(0, 0, -0.5)), material,
                   true);
}

inline std::unique_ptr<NativeBackend> makeBackend(const Scene& s, NativeSettings settings = {}) {
    return std::make_unique<NativeBackend>(s, settings);
}

}  // namespace vroc::native::test
