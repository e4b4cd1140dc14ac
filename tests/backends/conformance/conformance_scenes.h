// SPDX-License-Identifier: MIT
// Small scenes built in code for the conformance suite: each is what one contract clause needs.
#pragma once

#include <string>
#include <vector>

#include "test_scene_builder.h"
#include "vroc/core/convex_polyhedron.h"
#include "vroc/core/mass_properties.h"
#include "vroc/core/scene.h"

namespace vroc::conformance {

// The shared builders (tests/support/test_scene_builder.h), by their names here.
using vroc::test::addBody;
using vroc::test::at;

/// The shared empty scene with `gravity` [m/s^2]: material 0 (restitution 0.5, friction 0.5).
inline Scene sceneWithMaterial(const Vec3& gravity) {
    Scene s = vroc::test::emptyScene(0.5, 0.5);
    s.name = "conformance";
    s.gravity = gravity;
    return s;
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
    addBody(s, "floor", Shape::box(Vec3(5, 5, 0.5)), at(Vec3(0, 0, -100)), 0, true);
    addBody(s, "body", std::move(shape), at(Vec3(0.1, -0.2, 1.0), Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()))),
            0, false, 2.0);
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
