// SPDX-License-Identifier: MIT
// Small scenes built in code for the conformance suite: each is what one contract clause needs.
#pragma once

#include <string>
#include <vector>

#include "vroc/core/convex_polyhedron.h"
#include "vroc/core/mass_properties.h"
#include "vroc/core/scene.h"

namespace vroc::conformance {

inline Pose poseAt(const Vec3& p, const Quat& q = Quat::Identity()) {
    Pose pose;
    pose.position = p;
    pose.orientation = q;
    return pose;
}

inline Scene sceneWithMaterial(const Vec3& gravity) {
    Scene s;
    s.name = "conformance";
    s.gravity = gravity;
    s.collision_distance = 1e-3;
    s.frame_dt = 1.0 / 60.0;
    Material m;
    m.name = "m";
    m.restitution = 0.5;
    m.friction = 0.5;
    s.materials.push_back(m);
    return s;
}

inline int addBody(Scene& s, const std::string& name, Shape shape, const Pose& pose, bool real, double mass = 2.0) {
    Body b;
    b.name = name;
    b.role = real ? BodyRole::Real : BodyRole::Virtual;
    b.material = 0;
    b.shape = std::move(shape);
    b.pose = pose;
    if (!real) b.mass_properties = massProperties(b.shape, mass);
    s.bodies.push_back(std::move(b));
    return static_cast<int>(s.bodies.size()) - 1;
}

/// An irregular hull (8 points, no symmetry): its centre of mass is off the body origin and its
/// principal axes are not the body axes, which is what the frame conversions must get right.
inline Shape irregularHull() {
    const std::vector<Vec3> pts{{0.30, 0.05, 0.0}, {-0.2, 0.25, 0.1}, {-0.15, -0.2, 0.05}, {0.1, -0.1, 0.35},
                                {0.05, 0.15, -0.25}, {0.25, 0.2, 0.2}, {-0.1, 0.0, -0.2}, {0.0, -0.25, 0.15}};
    return Shape::convexHull(ConvexPolyhedron::fromPoints(pts));
}

/// One free virtual body of `shape` in zero gravity with nothing to touch (and a real floor far
/// below, so the scene has a real body): the momentum and round-trip clauses.
inline Scene lonelyBody(Shape shape) {
    Scene s = sceneWithMaterial(Vec3::Zero());
    addBody(s, "floor", Shape::box(Vec3(5, 5, 0.5)), poseAt(Vec3(0, 0, -100)), true);
    addBody(s, "body", std::move(shape), poseAt(Vec3(0.1, -0.2, 1.0), Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()))),
            false);
    return s;
}

/// lonelyBody with its body made tracked: moving at (0.5, -0.25, 0.1) m/s, turning at 0.8 rad/s.
inline Scene lonelyTrackedBody(Shape shape) {
    Scene s = lonelyBody(std::move(shape));
    Body& b = s.bodies[1];
    b.role = BodyRole::Tracked;
    b.mass_properties = MassProperties{};
    b.linear_velocity = Vec3(0.5, -0.25, 0.1);
    b.angular_velocity = Vec3(0.0, 0.0, 0.8);
    return s;
}

}  // namespace vroc::conformance
