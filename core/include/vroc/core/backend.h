// SPDX-License-Identifier: MIT
// The physics backend interface. Backends live in backends/<name>/, depend on core only and are
// registered by name in the BackendRegistry; nothing in core knows a backend by name.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "vroc/core/math.h"
#include "vroc/core/scene.h"
#include "vroc/core/settings.h"

namespace vroc {

/// State of one body, as every backend reports it.
struct BodyState {
    Pose pose;                                ///< body frame (as the scene defines it) -> world
    Vec3 linear_velocity = Vec3::Zero();      ///< [m/s] velocity of the centre of mass, world frame
    Vec3 angular_velocity = Vec3::Zero();     ///< [rad/s] world frame
};

/// One collision (docs/events.md): a pair that was not touching at the end of the previous
/// internal step receives a positive normal impulse while touching.
struct CollisionEvent {
    double time = 0.0;            ///< [s] simulation time of the contact
    int body_a = -1;              ///< scene body indices, body_a < body_b
    int body_b = -1;
    Vec3 point = Vec3::Zero();    ///< [m] contact point, world frame
    Vec3 normal = Vec3::Zero();   ///< unit normal pointing from a to b, world frame
    double impulse = 0.0;         ///< [N s] normal impulse of this collision (>= 0)
};

/// Counted numerical warnings by kind ("walk_not_converged", "nan_state", ...). Never NaN out.
using WarningCounts = std::map<std::string, std::uint64_t>;
/// Backend statistics by name (counts and means), for run.json.
using Statistics = std::map<std::string, double>;

class Backend {
public:
    virtual ~Backend() = default;

    /// Advances the simulation by one frame of `dt` [s] (> 0). Internal sub-stepping is the
    /// backend's business. Never throws on numerical trouble: it counts a warning and recovers.
    virtual void stepFrame(double dt) = 0;
    /// [s] current simulation time (sum of frame dts).
    virtual double time() const = 0;

    virtual int bodyCount() const = 0;
    virtual BodyState bodyState(int body) const = 0;
    /// Sets a virtual body's pose and velocities directly (devices grab and throw through this).
    /// Ignored for real (static) bodies.
    virtual void setBodyState(int body, const BodyState& state) = 0;
    /// Applies an impulse [N s] at a world point [m] to a virtual body.
    virtual void applyImpulse(int body, const Vec3& impulse, const Vec3& world_point) = 0;

    /// Collision events since the previous call, in time order.
    virtual std::vector<CollisionEvent> takeEvents() = 0;
    virtual WarningCounts warnings() const = 0;
    virtual Statistics statistics() const = 0;
};

/// What a backend tells the registry about itself.
struct BackendInfo {
    std::string name;             ///< used with --backend
    std::string description;      ///< one line
    std::string version;          ///< backend and underlying library version, e.g. "bullet 3.24 (double)"
    std::vector<SettingSpec> settings;
    /// Creates a backend for the scene. Throws InputError for settings the scene cannot honour.
    std::unique_ptr<Backend> (*create)(const Scene& scene, const Settings& settings) = nullptr;
};

}  // namespace vroc
