// SPDX-License-Identifier: MIT
// vroc::Backend over one ODE world (dWorld + dHashSpace + a contact joint group), owned by the
// backend. Frames:
//  - the scene's body frame (what BodyState.pose reports), and
//  - the ODE body frame: origin at the centre of mass c (body frame), axes the body frame's.
//    ODE keeps a full inertia tensor about the COM, so no principal frame is needed:
//    T_world_ode = T_world_body * (c, identity).
// Real bodies have no ODE body: their geoms sit in the world at the scene pose.
// Tracked bodies are ODE kinematic bodies (dBodySetKinematic: infinite mass, their velocity in the
// contact rows), frame = scene body frame (COM at the origin), put at the tracker motion's pose
// and velocities after every step (tracked_motion.h); the contact callback skips pairs with no
// dynamic body (real-real, tracked-real, tracked-tracked).
//
// One internal step: contact joints from the contacts found at the step's start, dWorldQuickStep
// (or dWorldStep), joint feedback read, joints emptied, non-finite bodies restored, then the
// collision pass at the new poses, which gives both the pairs touching after the step (events) and
// the next step's contacts (the same order of work as ODE's usual collide-step-empty loop).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <ode/ode.h>

#include "contact_generation.h"
#include "ode_config.h"
#include "ode_runtime.h"
#include "shape_mapping.h"
#include "vroc/core/tracked_motion.h"
#include "vroc/core/backend.h"
#include "vroc/core/contact_pair_tracker.h"

namespace vroc::ode {

class OdeBackend final : public Backend {
public:
    /// Throws InputError (before any ODE object exists) for a scene ODE cannot represent.
    OdeBackend(const Scene& scene, const OdeConfig& config);
    ~OdeBackend() override;
    OdeBackend(const OdeBackend&) = delete;
    OdeBackend& operator=(const OdeBackend&) = delete;

    void stepFrame(double dt) override;
    double time() const override { return time_; }
    int bodyCount() const override { return static_cast<int>(bodies_.size()); }
    BodyState bodyState(int body) const override;
    void setBodyState(int body, const BodyState& state) override;
    void applyImpulse(int body, const Vec3& impulse, const Vec3& world_point) override;
    std::vector<CollisionEvent> takeEvents() override { return events_.take(); }
    WarningCounts warnings() const override;
    Statistics statistics() const override;

private:
    /// ODE body state: COM position and velocity, orientation, angular velocity, all world.
    struct ComState {
        Vec3 position = Vec3::Zero();
        Quat orientation = Quat::Identity();
        Vec3 linear_velocity = Vec3::Zero();
        Vec3 angular_velocity = Vec3::Zero();
    };
    struct BodyRecord {
        dBodyID body = nullptr;               ///< owned by world_; null for a real body
        Pose static_pose;                     ///< real body: scene pose
        Vec3 com = Vec3::Zero();              ///< [m] centre of mass in the body frame
        double mass = 0.0;                    ///< [kg]
        Mat3 inertia = Mat3::Zero();          ///< [kg m^2] about the COM, body axes (= ODE body axes)
        ComState last_good;                   ///< after the last internal step that left it finite
        BodyRole role = BodyRole::Virtual;
        TrackedMotion motion;                 ///< tracked: the last tracker sample (or the file's motion)
    };

    BodyRecord& record(int body, const char* what);   ///< throws InputError if out of range
    void addBody(int index, const Body& body);
    void internalStep(double h, double end_time);
    void restoreNonfinite();
    ComState comState(const BodyRecord& rec) const;
    void setComState(BodyRecord& rec, const ComState& s);
    void placeTracked(BodyRecord& rec, double time);   ///< kinematic body at its motion's pose at `time` [s]

    OdeConfig config_;
    // Declaration order is destruction order reversed: the contact group, then the space with
    // its geoms, then the world with its bodies, and last the hull arrays the geoms point into.
    ShapeMapper shapes_;
    struct WorldDeleter { void operator()(dxWorld* w) const { dWorldDestroy(w); } };
    struct SpaceDeleter { void operator()(dxSpace* s) const { dSpaceDestroy(s); } };
    struct GroupDeleter { void operator()(dxJointGroup* g) const { dJointGroupDestroy(g); } };
    std::unique_ptr<dxWorld, WorldDeleter> world_;
    std::unique_ptr<dxSpace, SpaceDeleter> space_;
    std::unique_ptr<dxJointGroup, GroupDeleter> contact_group_;

    std::vector<BodyRecord> bodies_;
    ContactGenerator contacts_;
    bool contacts_current_ = false;             ///< contacts_ describes the current poses
    std::vector<dJointFeedback> feedback_;      ///< one per contact joint of the step in progress
    /// Collision events (docs/events.md) from the step's contact joints with their feedback impulses
    /// and the pairs the collision pass finds touching after the step. ODE finds a pair touching at
    /// the end of one step and acts on it in the next, so touching keeps a contact but never starts
    /// one, and a pair closer than the collision distance but not touching keeps none (ODE's
    /// colliders see no gap).
    ContactPairTracker events_{TouchingRule::KeepsContact};
    OdeMessageCounts messages_;                 ///< ODE's recovered-trouble messages
    unsigned long random_seed_ = 0;             ///< this world's share of ODE's random generator
    double time_ = 0.0;                         ///< [s] sum of frame dts
    std::uint64_t frames_ = 0, internal_steps_ = 0, nonfinite_ = 0, step_failures_ = 0;
    std::uint64_t contact_points_ = 0, contact_points_total_ = 0;
    std::uint64_t broadphase_pairs_ = 0, broadphase_pairs_total_ = 0;
};

}  // namespace vroc::ode
