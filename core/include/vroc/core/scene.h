// SPDX-License-Identifier: MIT
// The scene model: what a `vroc-scene/1` file describes, after loading and validation.
// Every backend is created from this and nothing else.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "vroc/core/mass_properties.h"
#include "vroc/core/math.h"
#include "vroc/core/shape.h"

namespace vroc {

struct Material {
    std::string name;
    double restitution = 0.5;   ///< [-] in [0, 1]
    double friction = 0.5;      ///< [-] Coulomb coefficient, >= 0
};

/// Contact material of a pair: restitution is the minimum (as in VROC 1995), friction the
/// geometric mean. Every backend must use exactly this.
struct ContactMaterial {
    double restitution;
    double friction;
};
ContactMaterial combineMaterials(const Material& a, const Material& b);

enum class BodyRole {
    Real,      ///< part of the model of the real world: static, infinite mass
    Virtual,   ///< dynamic
};

struct Body {
    std::string name;                         ///< unique within the scene
    BodyRole role = BodyRole::Virtual;
    int material = 0;                         ///< index into Scene::materials
    Shape shape;                              ///< in the body frame
    Pose pose;                                ///< body frame -> world at t = 0
    Vec3 linear_velocity = Vec3::Zero();      ///< [m/s] of the centre of mass, world frame
    Vec3 angular_velocity = Vec3::Zero();     ///< [rad/s] world frame
    MassProperties mass_properties;           ///< Virtual: mass, COM (body frame), inertia about COM
                                              ///< (body axes; the file's `inertia` override if given).
                                              ///< Real: mass 0, inertia zero.
    bool isStatic() const { return role == BodyRole::Real; }
};

struct Scene {
    std::string name;
    std::string description;
    std::string source_path;                  ///< file it was loaded from ("" if built in code)
    std::string source_sha256;                ///< hex SHA-256 of the file bytes
    Vec3 gravity = Vec3(0, 0, -9.81);         ///< [m/s^2] world frame
    double frame_dt = 1.0 / 60.0;             ///< [s] default frame step
    double collision_distance = 1e-3;         ///< [m] largest distance at which two objects touch
    std::vector<Material> materials;
    std::vector<Body> bodies;

    int findBody(const std::string& name) const;   ///< -1 if absent
    std::size_t virtualBodyCount() const;
};

}  // namespace vroc
