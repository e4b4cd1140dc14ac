// SPDX-License-Identifier: MIT
#include "ode_test_scenes.h"

#include "vroc/ode/ode_backend.h"

namespace vroc::test {

std::unique_ptr<Backend> makeOde(const Scene& scene, const Overrides& overrides) {
    ode::registerBackend();
    return makeRegistered("ode", scene, overrides);
}

BodyState restedCube(const Shape& shape, const Vec3& at, const Overrides& overrides, bool hull_floor) {
    Scene scene = emptyScene(0.0, 0.5);
    if (hull_floor) {
        Body floor;
        floor.name = "slab";
        floor.role = BodyRole::Real;
        floor.shape = Shape::convexHull(cuboidHull(Vec3(1, 1, 0.1)));
        floor.pose.position = Vec3(0, 0, -0.1);
        scene.bodies.push_back(floor);
    } else {
        addFloor(scene);
    }
    Body b;
    b.name = "cube";
    b.shape = shape;
    b.pose.position = at;
    b.mass_properties.mass = 1.0;
    b.mass_properties.inertia = cuboidInertia(Vec3(0.1, 0.1, 0.1), 1.0);
    scene.bodies.push_back(b);
    auto backend = makeOde(scene, overrides);
    for (int f = 0; f < 120; ++f) backend->stepFrame(scene.frame_dt);
    return backend->bodyState(1);
}

}  // namespace vroc::test
