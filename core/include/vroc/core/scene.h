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

/// How a material sounds when struck (hmd/audio, docs/scene-format.md#materials): a few damped
/// modes, mode i ringing as gains[i] e^(-decay_per_s[i] t) cos(2 pi modes_hz[i] t). The three
/// vectors have equal lengths (1 to kMaxSoundModes). The defaults (used when a material has no
/// `sound` object) are a stated generic knock, not derived from the other material properties:
/// the first four modes of a free-free bar (frequency ratios 1 : 2.756 : 5.404 : 8.933) on 600 Hz.
struct MaterialSound {
    static constexpr std::size_t kMaxSoundModes = 32;
    /// [Hz] below this: the Nyquist frequency (22.05 kHz) of the lowest sample rate the synthesiser
    /// accepts (44.1 kHz), with a margin, so every mode is representable at every accepted rate.
    static constexpr double kMaxModeHz = 20000.0;
    static constexpr double kMinDecayPerS = 0.5;    ///< [1/s] rings at most ~18 s to -80 dB
    static constexpr double kMaxDecayPerS = 1e5;    ///< [1/s]
    std::vector<double> modes_hz = {600.0, 1653.6, 3242.4, 5359.8};   ///< [Hz] in (0, kMaxModeHz]
    std::vector<double> decay_per_s = {40.0, 60.0, 90.0, 130.0};      ///< [1/s] amplitude decay rate
    std::vector<double> gains = {1.0, 0.5, 0.25, 0.125};              ///< [-] >= 0, relative amplitude
};

struct Material {
    std::string name;
    double restitution = 0.5;   ///< [-] in [0, 1]
    double friction = 0.5;      ///< [-] Coulomb coefficient, >= 0
    MaterialSound sound{};      ///< the file's `sound` object, or the stated defaults ({} keeps
                                ///< {name, restitution, friction} initialisers warning-free)
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
    Tracked,   ///< a real object that moves: its pose comes from a device (or, without one, it moves
               ///< at its file velocities); infinite mass, never moved by collisions, its velocity
               ///< enters the impulse (a kinematic body)
};

/// Where a tracked body's pose comes from. The body frame is the sensor frame: the device's pose
/// (sensor -> world) is the body's pose.
struct TrackingSource {
    std::string device;   ///< plugin spec "plugin:key=value,..." (docs/plugin-abi.md); "" = none, the
                          ///< body moves at its file velocities (deterministic; what the harness runs)
    int sensor = 0;       ///< sensor index of that device
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
                                              ///< Real and Tracked: mass 0, inertia zero, COM at the
                                              ///< body origin (velocities are the origin's).
    TrackingSource tracking;                  ///< Tracked only
    bool isStatic() const { return role == BodyRole::Real; }       ///< never moves
    bool isTracked() const { return role == BodyRole::Tracked; }   ///< moves, kinematically
    bool isDynamic() const { return role == BodyRole::Virtual; }   ///< moved by forces and impulses
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
