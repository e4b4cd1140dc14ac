// SPDX-License-Identifier: MIT
#include "vroc/core/body_motion_checks.h"

#include <cmath>

#include <Eigen/Cholesky>

#include "vroc/core/errors.h"

namespace vroc {

void checkBodiesForEngine(const Scene& scene, const std::string& engine,
                          const std::function<std::string(const Shape&)>& unsupported) {
    for (const Body& body : scene.bodies) {
        const std::string where = engine + ": scene '" + scene.name + "': body '" + body.name + "': ";
        if (body.material < 0 || static_cast<std::size_t>(body.material) >= scene.materials.size())
            throw InputError(where + "material index " + std::to_string(body.material) + " out of range");
        const std::string why = unsupported(body.shape);
        if (!why.empty()) throw InputError(where + body.shape.kindName() + " shape not supported: " + why);
        if (!body.pose.position.allFinite() || !body.pose.orientation.coeffs().allFinite() ||
            !(body.pose.orientation.norm() > 0.0))
            throw InputError(where + "expected a finite pose with a non-zero quaternion");
        if (body.isStatic()) continue;
        if (!hasFiniteMotion(body)) throw InputError(where + "expected finite initial velocities");
        if (body.isTracked()) continue;   // infinite mass: no mass properties
        const MassProperties& mp = body.mass_properties;
        const Mat3 sym = 0.5 * (mp.inertia + mp.inertia.transpose());
        if (!(mp.mass > 0.0) || !std::isfinite(mp.mass) || !mp.inertia.allFinite() || !mp.center_of_mass.allFinite() ||
            sym.llt().info() != Eigen::Success)
            throw InputError(where + "a virtual body needs a positive finite mass and a positive definite inertia");
    }
}

}  // namespace vroc
