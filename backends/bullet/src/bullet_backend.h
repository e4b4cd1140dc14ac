// SPDX-License-Identifier: MIT
// vroc::Backend over btDiscreteDynamicsWorld (double precision). Internal frames:
//  - the scene's body frame (what BodyState.pose reports), and
//  - Bullet's rigid-body frame at the centre of mass along the principal axes of inertia;
//    `com_in_body` maps the second into the first.
// Real bodies are static (mass 0) and placed at their scene pose directly. Tracked bodies are
// Bullet kinematic bodies (CF_KINEMATIC_OBJECT): their frame is the scene body frame (COM at the
// origin), placed at the tracker motion's pose at the start of every internal step, and given its
// velocities in the world's pre-tick callback (after Bullet's own finite-difference estimate), so
// the solver sees the motion.
#pragma once

#include <memory>
#include <vector>

#include "bullet_config.h"
#include "event_detection.h"
#include "shape_mapping.h"
#include "vroc/core/tracked_motion.h"
#include "vroc/core/backend.h"

class btDefaultCollisionConfiguration;
class btCollisionDispatcher;
class btBroadphaseInterface;
class btSequentialImpulseConstraintSolver;
class btDiscreteDynamicsWorld;
class btDynamicsWorld;
class btRigidBody;

namespace vroc::bullet {

class BulletBackend final : public Backend {
public:
    BulletBackend(const Scene& scene, const BulletConfig& config);
    ~BulletBackend() override;

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
    struct BodyRecord {
        std::unique_ptr<btRigidBody> rigid;   ///< owned; registered with world_
        Pose com_in_body;                     ///< Bullet body frame -> scene body frame
        BodyRole role = BodyRole::Virtual;
        BodyState last_good;                  ///< Bullet COM frame state after the last internal step
                                              ///< that left it finite and simulated
        TrackedMotion motion;                 ///< tracked: the last tracker sample (or the file's motion)
    };

    void configureSolver();
    void addBody(int index, const Body& body);
    BodyRecord& record(int body, const char* what);   ///< throws InputError if out of range
    void internalStep(double h, double end_time);
    void recoverBadStates();
    BodyState comState(const btRigidBody& rigid) const;
    void setComState(btRigidBody& rigid, const BodyState& com_state);
    void placeTracked(BodyRecord& rec, double time);   ///< kinematic body at its motion's pose at `time` [s]
    void holdTrackedVelocities();                      ///< the tracker velocities, exactly (pre-tick)
    static void preTick(btDynamicsWorld* world, double h);   ///< Bullet's internal pre-tick callback

    BulletConfig config_;
    Vec3 gravity_;
    std::unique_ptr<btDefaultCollisionConfiguration> collision_config_;
    std::unique_ptr<btCollisionDispatcher> dispatcher_;
    std::unique_ptr<btBroadphaseInterface> broadphase_;
    std::unique_ptr<btSequentialImpulseConstraintSolver> solver_;
    std::unique_ptr<btDiscreteDynamicsWorld> world_;
    ShapeMapper shapes_;
    std::vector<BodyRecord> bodies_;
    std::vector<int> tracked_;                ///< indices of the tracked bodies
    EventDetector events_;
    double time_ = 0.0;                       ///< [s] sum of frame dts
    std::uint64_t frames_ = 0, internal_steps_ = 0, nonfinite_ = 0, aabb_overflow_ = 0, ccd_bodies_ = 0;
};

}  // namespace vroc::bullet
