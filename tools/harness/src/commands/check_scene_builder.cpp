// SPDX-License-Identifier: MIT
#include "check_scene_builder.h"

#include "vroc/core/mass_properties.h"

namespace vroc::harness {

Scene emptyScene(const std::string& name, const Vec3& gravity, double frame_dt) {
    Scene s;
    s.name = name;
    s.description = "built in code by vroc check";
    s.gravity = gravity;
    s.frame_dt = frame_dt;
    return s;
}

int addMaterial(Scene& scene, double restitution, double friction) {
    std::string name = "m";
    name += std::to_string(scene.materials.size());
    scene.materials.push_back({name, restitution, friction});
    return static_cast<int>(scene.materials.size()) - 1;
}

int addBody(Scene& scene, const std::string& name, Shape shape, double mass, const Pose& pose, int material,
            const Vec3& velocity, const Vec3& angular_velocity) {
    Body b;
    b.name = name;
    b.role = mass > 0 ? BodyRole::Virtual : BodyRole::Real;
    b.material = material;
    b.shape = std::move(shape);
    b.pose = pose;
    if (mass > 0) {
        b.linear_velocity = velocity;
        b.angular_velocity = angular_velocity;
        b.mass_properties = massProperties(b.shape, mass);
    }
    scene.bodies.push_back(std::move(b));
    return static_cast<int>(scene.bodies.size()) - 1;
}

int addTracked(Scene& scene, const std::string& name, Shape shape, const Pose& pose, int material,
               const Vec3& velocity, const Vec3& angular_velocity) {
    Body b;
    b.name = name;
    b.role = BodyRole::Tracked;
    b.material = material;
    b.shape = std::move(shape);
    b.pose = pose;
    b.linear_velocity = velocity;
    b.angular_velocity = angular_velocity;
    scene.bodies.push_back(std::move(b));
    return static_cast<int>(scene.bodies.size()) - 1;
}

int addGround(Scene& scene, double hx, double hy, int material) {
    return addBody(scene, "ground", Shape::box(Vec3(hx, hy, 0.5)), 0, at(Vec3(0, 0, -0.5)), material);
}

Pose at(const Vec3& position) { return Pose{position, Quat::Identity()}; }

}  // namespace vroc::harness
