// SPDX-License-Identifier: MIT
#include "checks/landing_check.h"

#include <cmath>
#include <exception>
#include <vector>

#include "checks/check_support.h"
#include "test_scene_builder.h"
#include "vroc/core/mass_properties.h"

namespace vroc::conformance {
namespace {

struct DroppedShape {
    Shape shape;
    Support support = Support::Exact;  ///< as the backend declares the shape kind
};

/// One of each kind, none of them symmetric about the body origin where it matters: the hull's
/// centre of mass is off its origin, the compound's parts differ.
std::vector<DroppedShape> droppedShapes(const BackendCapabilities& c) {
    const Vec3 plate(0.2, 0.15, 0.05);
    ConvexPolyhedron hull = vroc::test::cuboidHull(plate, Quat::Identity(), Vec3(0.05, -0.03, 0.02));
    return {{Shape::sphere(0.1), c.sphere},
            {Shape::box(Vec3(0.15, 0.1, 0.05)), c.box},
            {Shape::convexHull(std::move(hull)), c.hull},
            {Shape::compound({{Shape::box(Vec3(0.1, 0.1, 0.05)), vroc::test::at(Vec3(-0.15, 0, 0))},
                              {Shape::sphere(0.05), vroc::test::at(Vec3(0.15, 0, 0))}}),
             c.compound}};
}

/// A real floor (top face z = 0, body 0) and the shape as virtual body 1, 1 kg, its lowest point
/// `drop_height` above the floor; restitution 0, friction 0.5.
Scene dropScene(const Shape& shape, double drop_height) {
    Scene s = vroc::test::emptyScene(0.0, 0.5);
    s.name = std::string("landing ") + shape.kindName();
    vroc::test::addFloor(s);
    const double lift = drop_height - lowestZ(shape, Pose{});
    vroc::test::addBody(s, "body", shape, vroc::test::at(Vec3(0, 0, lift)), 0, false, 1.0);
    return s;
}

void checkDrop(const BackendInfo& backend, const DroppedShape& d, const LandingCheckOptions& options, CheckResult& r) {
    const Scene scene = dropScene(d.shape, options.drop_height);
    const std::string where = std::string(d.shape.kindName()) + " dropped onto the floor";
    auto b = createBackend(backend, scene);
    bool touched = false;
    const int frames = static_cast<int>(std::ceil(options.duration / scene.frame_dt));
    for (int f = 0; f < frames; ++f) {
        b->stepFrame(scene.frame_dt);
        for (const CollisionEvent& e : b->takeEvents())
            if (e.body_a == 0 && e.body_b == 1 && e.impulse > 0.0) touched = true;
    }
    const BodyState s = b->bodyState(1);
    const double gap = lowestZ(d.shape, s.pose);
    const double tol = d.support == Support::Exact ? options.exact_tolerance : options.approximated_tolerance;
    if (!touched) r.fail(where, ": no collision event with the floor in ", options.duration, " s");
    if (!(gap >= -tol && gap <= scene.collision_distance + tol))
        r.fail(where, " (", supportName(d.support), "): lowest point ", gap, " m from the floor after ",
               options.duration, " s (within ", tol, " m of [0, ", scene.collision_distance, "] expected)");
    const double speed = s.linear_velocity.norm();
    if (!(speed < options.rest_speed))
        r.fail(where, ": still moving at ", speed, " m/s after ", options.duration, " s");
}

}  // namespace

CheckResult checkLanding(const BackendInfo& backend, const LandingCheckOptions& options) {
    CheckResult r{backend.name, {}};
    int dropped = 0;
    for (const DroppedShape& d : droppedShapes(backend.capabilities)) {
        if (d.support == Support::Unsupported) continue;  // refusal: checkShapeSupport
        ++dropped;
        try {
            checkDrop(backend, d, options, r);
        } catch (const std::exception& e) {
            r.fail(d.shape.kindName(), " dropped: threw ", e.what());
        }
    }
    if (dropped == 0) r.fail("every shape kind is declared unsupported: nothing dropped");
    return r;
}

}  // namespace vroc::conformance
