// SPDX-License-Identifier: MIT
#include "checks/impulse_check.h"

#include <exception>

#include "checks/check_support.h"
#include "conformance_scenes.h"

namespace vroc::conformance {

CheckResult checkImpulse(const BackendInfo& backend) {
    CheckResult r{backend.name, {}};
    try {
        const Scene scene = lonelyBody(irregularHull());
        const Body& body = scene.bodies[1];
        auto b = createBackend(backend, scene);
        b->stepFrame(scene.frame_dt);  // after a step, not only at the state the scene gave
        const BodyState before = b->bodyState(1);
        const Vec3 com = centreOfMass(body, before);
        const Vec3 impulse(0.8, -0.3, 1.1), point = com + Vec3(0.05, 0.12, -0.07);
        b->applyImpulse(1, impulse, point);
        const BodyState after = b->bodyState(1);
        const Vec3 dp = body.mass_properties.mass * (after.linear_velocity - before.linear_velocity);
        if ((dp - impulse).norm() > 1e-12 * 8)
            r.fail("lonely hull: momentum change ", dp, " for the world-frame impulse ", impulse);
        const Mat3 rot = before.pose.orientation.toRotationMatrix();
        const Vec3 dl =
            rot * body.mass_properties.inertia * rot.transpose() * (after.angular_velocity - before.angular_velocity);
        const Vec3 expected = (point - com).cross(impulse);
        if ((dl - expected).norm() > 1e-11)
            r.fail("lonely hull: angular momentum change ", dl, ", (p - com) x J = ", expected);
        if ((after.pose.position - before.pose.position).norm() > 1e-15)
            r.fail("lonely hull: an impulse moved the body by ", Vec3(after.pose.position - before.pose.position));
    } catch (const std::exception& e) {
        r.fail("lonely hull: threw ", e.what());
    }
    return r;
}

}  // namespace vroc::conformance
