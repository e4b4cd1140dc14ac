// SPDX-License-Identifier: MIT
// The physics backend interface. Backends live in backends/<name>/, depend on core only and are
// registered by name in the BackendRegistry; nothing in core knows a backend by name.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <utility>
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

/// Counted numerical warnings by kind. Names come from the shared vocabulary
/// (backend_vocabulary.h: `nonfinite_state`, ...) or carry the backend's prefix ("native.zeno_contact").
using WarningCounts = std::map<std::string, std::uint64_t>;
/// Backend statistics by name (counts and means), for run.json. Shared names
/// (backend_vocabulary.h: `frames`, `internal_steps`, `collision_events`, ...) or the backend's prefix.
using Statistics = std::map<std::string, double>;

/// The backend contract (docs/backend-contract.md). Every call is made from one thread at a time.
/// Errors: a caller's mistake (a body index out of range, a frame dt <= 0 or not finite, a scene or
/// setting the backend cannot represent) throws InputError. Numerical trouble never throws and
/// never leaves the backend: it is counted as a warning and the body keeps (or returns to) a finite
/// state. A non-finite state or impulse handed in through setBodyState / applyImpulse is such
/// trouble (a tracker glitch): counted as `nonfinite_state`, refused, the body unchanged.
/// Units SI, frames world unless said; the scene's body indices address bodies.
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
    /// For a tracked body it is a tracker sample: the body takes this pose at the current time and
    /// from then on moves at these velocities (linear of its origin, angular; no gravity, and
    /// collisions never change them) until the next call. Ignored for real (static) bodies.
    virtual void setBodyState(int body, const BodyState& state) = 0;
    /// Applies an impulse [N s] at a world point [m] to a virtual body.
    virtual void applyImpulse(int body, const Vec3& impulse, const Vec3& world_point) = 0;

    /// Collision events since the previous call, in time order.
    virtual std::vector<CollisionEvent> takeEvents() = 0;
    virtual WarningCounts warnings() const = 0;
    virtual Statistics statistics() const = 0;
};

/// How faithfully a backend represents one feature of a scene.
enum class Support {
    Exact,          ///< as the scene states it
    Approximated,   ///< represented, with a stated difference (BackendCapabilities::notes)
    Unsupported,    ///< refused: creating a backend for a scene that needs it throws InputError
};

/// Friction model of the contact solver.
enum class FrictionModel {
    Cone,       ///< Coulomb's circular cone
    Pyramid,    ///< a polygonal (usually 4-sided) approximation of the cone
};

/// What a backend can represent, declared once; the harness reads it so that a check or scene a
/// backend cannot represent faithfully is reported "not supported" or "approximated: why".
struct BackendCapabilities {
    Support sphere = Support::Unsupported;
    Support box = Support::Unsupported;
    Support hull = Support::Unsupported;       ///< convex polyhedra (vertices + faces)
    Support compound = Support::Unsupported;   ///< several convex parts on one rigid body
    Support restitution = Support::Unsupported;   ///< Newton's coefficient per collision
    Support tracked = Support::Unsupported;       ///< moving bodies of infinite mass (role "tracked")
    FrictionModel friction = FrictionModel::Cone;
    bool continuous_collision = false;   ///< no tunnelling at any speed (time of impact)
    bool deterministic = true;           ///< same scene, settings and build give the same bits
    std::string precision = "double";    ///< floating-point type of the solver
    /// Why each Approximated entry differs, by feature name ("restitution", "hull", ...).
    std::map<std::string, std::string> notes;
};

/// Name of a Support value ("exact", "approximated", "unsupported").
const char* supportName(Support s);
/// Name of a FrictionModel value ("cone", "pyramid").
const char* frictionName(FrictionModel f);

/// What a backend tells the registry about itself.
struct BackendInfo {
    std::string name;             ///< used with --backend
    std::string description;      ///< one line
    std::string version;          ///< backend and underlying library version, e.g. "bullet 3.24 (double)"
    BackendCapabilities capabilities;
    /// Settings that differ from the underlying engine's own defaults, with why: a fair comparison
    /// lists them in run.json ("sleeping off: every body stays awake on every backend").
    std::vector<std::string> deviations;
    std::vector<SettingSpec> settings;
    /// Creates a backend for the scene. Throws InputError for settings the scene cannot honour.
    std::unique_ptr<Backend> (*create)(const Scene& scene, const Settings& settings) = nullptr;
    /// The equal footing of a fair comparison (`--footing equal`, docs/harness.md): the settings that
    /// make the engine take `substeps` internal steps per frame and use Coulomb's isotropic friction
    /// where it has it, as key=value pairs applied over its defaults (the user's --set still wins).
    /// Null: the engine has no such settings (it runs at its defaults on either footing).
    std::vector<std::pair<std::string, std::string>> (*equal_footing)(int substeps) = nullptr;
    /// The capabilities under these settings, for an engine whose settings change what it represents
    /// (mujoco.cone=elliptic gives Coulomb's cone). Null: `capabilities`, whatever the settings.
    BackendCapabilities (*capabilities_with)(const Settings& settings) = nullptr;

    /// capabilities_with(settings) when set, else capabilities.
    BackendCapabilities capabilitiesFor(const Settings& settings) const {
        return capabilities_with ? capabilities_with(settings) : capabilities;
    }
};

}  // namespace vroc
