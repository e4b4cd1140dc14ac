// SPDX-License-Identifier: MIT
// Scenes built in code for the tests: the one home of the builders every suite uses (backends,
// conformance, hmd, tools). Closed-form answers need exact set-ups, so each body's mass properties
// are either computed by vroc::massProperties (addBody) or written out in closed form (addBall,
// addBox, addHullCuboid: an independent answer for the mass-property code itself).
// Header-only: every test program includes it from tests/support (vroc_add_test_suite).
#pragma once

#include <cmath>
#include <string>
#include <utility>

#include "vroc/core/convex_polyhedron.h"
#include "vroc/core/mass_properties.h"
#include "vroc/core/scene.h"

namespace vroc::test {

/// Pose at position p [m] with orientation q.
inline Pose at(const Vec3& p, const Quat& q = Quat::Identity()) {
    Pose pose;
    pose.position = p;
    pose.orientation = q;
    return pose;
}

/// Scene "test" with no materials and no bodies: gravity [m/s^2], collision distance [m], frame dt 1/60 s.
inline Scene bareScene(double collision_distance = 1e-3, const Vec3& gravity = Vec3(0, 0, -9.81)) {
    Scene s;
    s.name = "test";
    s.gravity = gravity;
    s.frame_dt = 1.0 / 60.0;
    s.collision_distance = collision_distance;
    return s;
}

/// bareScene() with material 0, "default", of the given restitution and friction.
inline Scene emptyScene(double restitution = 0.5, double friction = 0.5) {
    Scene s = bareScene();
    s.materials.push_back({"default", restitution, friction});
    return s;
}

/// Adds a material, returns its index.
inline int addMaterial(Scene& scene, const std::string& name, double restitution, double friction) {
    scene.materials.push_back({name, restitution, friction});
    return static_cast<int>(scene.materials.size()) - 1;
}
/// Adds a material named "m<index>", returns its index.
inline int addMaterial(Scene& scene, double restitution, double friction) {
    std::string name = "m";
    name += std::to_string(scene.materials.size());   // two statements: GCC 12's -Wrestrict false positive
    return addMaterial(scene, name, restitution, friction);
}

/// Adds `b` to the scene, returns its index.
inline int addBody(Scene& scene, Body b) {
    scene.bodies.push_back(std::move(b));
    return static_cast<int>(scene.bodies.size()) - 1;
}

/// Adds a real (static) body when is_static, else a virtual one with the uniform-density mass
/// properties of `mass` [kg] (vroc::massProperties). Returns its index.
inline int addBody(Scene& scene, const std::string& name, Shape shape, const Pose& pose, int material, bool is_static,
                   double mass = 1.0) {
    Body b;
    b.name = name;
    b.role = is_static ? BodyRole::Real : BodyRole::Virtual;
    b.material = material;
    b.shape = std::move(shape);
    b.pose = pose;
    if (!is_static) b.mass_properties = massProperties(b.shape, mass);
    return addBody(scene, std::move(b));
}

/// Adds a tracked body (scene.h: infinite mass, mass properties zero) at `pose`, moving at
/// `velocity` [m/s] of its origin and `angular_velocity` [rad/s], world frame.
inline int addTracked(Scene& scene, const std::string& name, Shape shape, const Pose& pose, int material,
                      const Vec3& velocity, const Vec3& angular_velocity = Vec3::Zero()) {
    Body b;
    b.name = name;
    b.role = BodyRole::Tracked;
    b.material = material;
    b.shape = std::move(shape);
    b.pose = pose;
    b.linear_velocity = velocity;
    b.angular_velocity = angular_velocity;
    return addBody(scene, std::move(b));
}

/// Real box "floor", half extents (half_size, half_size, 0.5) m, whose top face is the plane z = 0.
inline int addFloor(Scene& scene, int material = 0, double half_size = 10.0) {
    return addBody(scene, "floor", Shape::box(Vec3(half_size, half_size, 0.5)), at(Vec3(0, 0, -0.5)), material, true);
}

/// Solid cuboid inertia about its centre, in its own axes [kg m^2]: m/3 (b^2 + c^2), ...
inline Mat3 cuboidInertia(const Vec3& h, double m) {
    return Vec3(m / 3 * (h.y() * h.y() + h.z() * h.z()), m / 3 * (h.x() * h.x() + h.z() * h.z()),
                m / 3 * (h.x() * h.x() + h.y() * h.y()))
        .asDiagonal();
}

/// Virtual solid sphere [m, kg] at `position`, closed form: I = 2/5 m r^2.
inline int addBall(Scene& scene, const std::string& name, double radius, double mass, const Vec3& position,
                   int material = 0) {
    Body b;
    b.name = name;
    b.material = material;
    b.shape = Shape::sphere(radius);
    b.pose.position = position;
    b.mass_properties.mass = mass;
    b.mass_properties.volume = 4.0 / 3.0 * M_PI * radius * radius * radius;
    b.mass_properties.inertia = Mat3::Identity() * (0.4 * mass * radius * radius);
    return addBody(scene, std::move(b));
}

/// Virtual solid box [half extents m, kg] at `position`, closed form (cuboidInertia).
inline int addBox(Scene& scene, const std::string& name, const Vec3& half, double mass, const Vec3& position,
                  int material = 0) {
    Body b;
    b.name = name;
    b.material = material;
    b.shape = Shape::box(half);
    b.pose.position = position;
    b.mass_properties.mass = mass;
    b.mass_properties.volume = 8 * half.prod();
    b.mass_properties.inertia = cuboidInertia(half, mass);
    return addBody(scene, std::move(b));
}

/// A cuboid as a hull (faces and planes filled in by hand), vertices rotated by `rot` and shifted
/// by `centre` in the body frame.
inline ConvexPolyhedron cuboidHull(const Vec3& half, const Quat& rot = Quat::Identity(),
                                   const Vec3& centre = Vec3::Zero()) {
    ConvexPolyhedron p;
    for (int i = 0; i < 8; ++i) {
        const Vec3 local((i & 1) ? half.x() : -half.x(), (i & 2) ? half.y() : -half.y(), (i & 4) ? half.z() : -half.z());
        p.vertices.push_back(rot * local + centre);
    }
    // Faces counter-clockwise seen from outside: -x, +x, -y, +y, -z, +z.
    p.faces = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    const Vec3 axes[6] = {-Vec3::UnitX(), Vec3::UnitX(), -Vec3::UnitY(), Vec3::UnitY(), -Vec3::UnitZ(), Vec3::UnitZ()};
    for (const Vec3& axis : axes) {
        const Vec3 n = rot * axis;
        p.face_normals.push_back(n);
        p.face_offsets.push_back(n.dot(centre) + std::abs(axis.dot(half)));
    }
    return p;
}

/// Virtual cuboidHull body at `pose`, closed form: COM = centre_in_body, inertia R diag R^T.
inline int addHullCuboid(Scene& scene, const std::string& name, const Vec3& half, double mass, const Pose& pose,
                         const Quat& rot_in_body = Quat::Identity(), const Vec3& centre_in_body = Vec3::Zero(),
                         int material = 0) {
    Body b;
    b.name = name;
    b.material = material;
    b.shape = Shape::convexHull(cuboidHull(half, rot_in_body, centre_in_body));
    b.pose = pose;
    b.mass_properties.mass = mass;
    b.mass_properties.volume = 8 * half.prod();
    b.mass_properties.center_of_mass = centre_in_body;
    const Mat3 R = rot_in_body.toRotationMatrix();
    b.mass_properties.inertia = R * cuboidInertia(half, mass) * R.transpose();
    return addBody(scene, std::move(b));
}

}  // namespace vroc::test
