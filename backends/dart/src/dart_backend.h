// SPDX-License-Identifier: MIT
// vroc::Backend over one DART World (FCL collision, DART's boxed LCP constraint solver), owned by
// the backend. Every scene body is a Skeleton of one FreeJoint and one BodyNode. Frames:
//  - the scene's body frame (what BodyState.pose reports), and
//  - the DART body frame: for a virtual body its centre of mass c with the scene body's axes
//    (DART takes a full inertia tensor: T_world_dart = T_world_body * (c, identity)), so that the
//    FreeJoint's velocity is the centre of mass's; for real and tracked bodies the scene body frame.
// Real bodies are immobile skeletons (Skeleton::setMobile(false)) at the scene pose. Tracked bodies
// have a VELOCITY-actuated FreeJoint (DART's prescribed motion: not reactive, so an infinite mass
// to the contact solver, with its velocity in the contact rows), given the tracker motion's
// velocity before each step and put at its pose and velocity after it (tracked_motion.h).
// Materials: contact_classes.h. One internal step is World::step: forward dynamics, collision and
// the constraint solve at the step's start, then positions; non-finite bodies are then restored.
#pragma once

#include <cstdint>
#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/FreeJoint.hpp>
#include <dart/dynamics/ShapeNode.hpp>
#include <dart/dynamics/Skeleton.hpp>
#include <dart/simulation/World.hpp>
#include <memory>
#include <vector>

#include "contact_classes.h"
#include "dart_config.h"
#include "sized_lcp_solver.h"
#include "vroc/core/backend.h"
#include "vroc/core/contact_pair_tracker.h"
#include "vroc/core/tracked_motion.h"

namespace vroc::dart {

class DartBackend final : public Backend {
public:
    /// Throws InputError (before any DART object exists) for a scene DART cannot represent.
    DartBackend(const Scene& scene, const DartConfig& config);
    ~DartBackend() override;
    DartBackend(const DartBackend&) = delete;
    DartBackend& operator=(const DartBackend&) = delete;

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
    /// The DART body frame's state: origin (the COM for a virtual body), orientation, origin
    /// velocity and angular velocity, all world.
    struct FrameState {
        Vec3 position = Vec3::Zero();
        Quat orientation = Quat::Identity();
        Vec3 linear_velocity = Vec3::Zero();
        Vec3 angular_velocity = Vec3::Zero();
    };
    struct BodyRecord {
        ::dart::dynamics::SkeletonPtr skeleton;            ///< owned (shared with world_)
        ::dart::dynamics::FreeJoint* joint = nullptr;      ///< owned by skeleton
        ::dart::dynamics::BodyNode* node = nullptr;        ///< owned by skeleton
        std::vector<::dart::dynamics::ShapeNode*> shapes;  ///< owned by node
        BodyRole role = BodyRole::Virtual;
        Pose static_pose;             ///< real body: scene pose
        Vec3 com = Vec3::Zero();      ///< [m] centre of mass in the body frame (virtual; else 0)
        double mass = 0.0;            ///< [kg] virtual
        Mat3 inertia = Mat3::Zero();  ///< [kg m^2] about the COM, body axes (virtual)
        FrameState last_good;         ///< after the last step that left it finite
        TrackedMotion motion;         ///< tracked: the last tracker sample (or the file's motion)
    };

    BodyRecord& record(int body, const char* what);  ///< throws InputError if out of range
    void addBody(int index, const Body& body, const MaterialClasses& classes);
    void addShapes(BodyRecord& rec, const Body& body, const Pose& shape_frame_in_dart, const MaterialClasses& classes,
                   int index);
    void internalStep(double h, double end_time);
    bool contactsFitted();  ///< the last step's contacts fitted the buffer (grows it if not)
    void saveStates();
    void restoreSavedStates();
    void restoreNonfinite();
    void alignFriction();  ///< dart.friction_axes=sliding: each virtual body's slide direction
    void readContacts(double h, double end_time);
    FrameState frameState(const BodyRecord& rec) const;
    void setFrameState(BodyRecord& rec, const FrameState& s);
    void placeTracked(BodyRecord& rec, double time);  ///< at its motion's pose and velocity at `time` [s]

    DartConfig config_;
    std::shared_ptr<ClassFilter> filter_;
    std::shared_ptr<SizedBoxedLcpSolver> lcp_;  ///< shared with world_'s constraint solver
    std::shared_ptr<::dart::simulation::World> world_;
    std::vector<BodyRecord> bodies_;
    std::vector<FrameState> saved_;  ///< states before the step in progress (growing contact buffer)
    std::size_t contact_capacity_ = 1000;
    bool mesh_for_hulls_ = false;  ///< spheres and hulls in one scene: FCL collides meshes (dart_backend.cpp)
    /// Collision events (docs/events.md) from the contacts the step's solver found at its start
    /// (World::getLastCollisionResult) with their solved impulses; every such contact's pair is
    /// touching. As in ODE, touching keeps a contact but never starts one: a pair the step found
    /// touching whose impulse is zero stays in contact only if it was before (readContacts).
    ContactPairTracker events_{TouchingRule::KeepsContact};
    double time_ = 0.0;  ///< [s] sum of frame dts
    std::uint64_t frames_ = 0, internal_steps_ = 0, nonfinite_ = 0, step_cap_ = 0, contact_cap_ = 0,
                  buffer_growths_ = 0;
    std::uint64_t contact_points_ = 0, contact_points_total_ = 0;
};

}  // namespace vroc::dart
