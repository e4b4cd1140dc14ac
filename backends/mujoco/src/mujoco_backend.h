// SPDX-License-Identifier: MIT
// vroc::Backend over MuJoCo 2.2 (mjModel compiled from the MJCF that mjcf_writer.h writes).
// Frames: a virtual body's MuJoCo body frame is its centre of mass along the principal axes
// (`com_in_body` maps it into the scene's body frame). Its free joint holds, in MuJoCo 2.2's
// convention, qpos = (position [m], quaternion w x y z body -> world) and qvel = (linear velocity
// of the body frame origin, here the COM, world [m/s]; angular velocity in the body's own frame
// [rad/s]). Real bodies are static MuJoCo bodies and report their scene pose. Tracked bodies are
// free bodies too (frame = scene body frame, trackedInertia() heavy): before each step their
// weight is cancelled through qfrc_applied, after it their qpos and qvel are set to the tracker
// motion's (tracked_motion.h), so MuJoCo's contacts see their velocity and never move them.
#pragma once

#include <cstdint>
#include <vector>

#include "event_detection.h"
#include "model_loader.h"
#include "mujoco_config.h"
#include "state_guard.h"
#include "vroc/core/tracked_motion.h"
#include "vroc/core/backend.h"

namespace vroc::mujoco {

class MujocoBackend final : public Backend {
public:
    MujocoBackend(const Scene& scene, const MujocoConfig& config);

    void stepFrame(double dt) override;
    double time() const override { return time_; }
    int bodyCount() const override { return static_cast<int>(bodies_.size()); }
    BodyState bodyState(int body) const override;
    void setBodyState(int body, const BodyState& state) override;
    void applyImpulse(int body, const Vec3& impulse, const Vec3& world_point) override;
    std::vector<CollisionEvent> takeEvents() override { return events_.take(); }
    WarningCounts warnings() const override;
    Statistics statistics() const override;

    /// The compiled model (tests compare masses and inertias with the scene).
    const mjModel& model() const { return *model_; }

private:
    struct BodyRecord {
        BodyRole role = BodyRole::Virtual;
        Pose pose;                     ///< static: the scene pose
        Pose com_in_body;              ///< MuJoCo body frame -> scene body frame
        BodySlots slots;               ///< free joint addresses (virtual)
        double mass = 0.0;             ///< [kg]
        Vec3 principal_inertia = Vec3::Zero();   ///< [kg m^2] in the MuJoCo body frame
        TrackedMotion motion;          ///< tracked: the last tracker sample (or the file's motion)
    };

    const BodyRecord& record(int body, const char* what) const;   ///< throws InputError if out of range
    BodyRecord& record(int body, const char* what);
    void internalStep(double h, double end_time);
    void mujocoStep(double h, double end_time);        ///< one checked mj_step (and its recovery)
    bool growBuffers(bool contacts, bool rows, bool stack);   ///< larger buffers, a new mjData
    static constexpr int kMaxGrowthsPerStep = 8;
    static constexpr double kMaxRowBytes = 1e9;   ///< [bytes] of njmax-sized arrays (MuJoCo 2.2's dense rows)
    void placeTracked(BodyRecord& rec, double time);   ///< qpos, qvel from the tracker motion at `time` [s]
    void holdTrackedWeight();                          ///< qfrc_applied = -m g on each tracked body
    Pose comPose(const BodyRecord& rec) const;

    MujocoConfig config_;
    ModelPtr model_;
    DataPtr data_;
    std::vector<BodyRecord> bodies_;
    EventDetector events_;
    StateGuard guard_;
    double time_ = 0.0;   ///< [s] sum of frame dts
    std::uint64_t frames_ = 0, internal_steps_ = 0, nonfinite_ = 0, step_cap_ = 0, solver_iterations_ = 0;
    int last_ncon_ = 0, last_nefc_ = 0;
    std::uint64_t buffer_growths_ = 0;   ///< steps taken again with larger buffers (growBuffers)
    std::uint64_t phantom_contacts_ = 0; ///< box-box contacts clamped (mujoco.bound_box_depth; per evaluation)
};

}  // namespace vroc::mujoco
