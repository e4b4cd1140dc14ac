// SPDX-License-Identifier: MIT
// One backend stepping one scene, as `vroc.Simulation` presents it (docs/python.md). Free of Python:
// the bindings add arrays and the GIL. The frame loop is core's (stepFrames), so a simulation
// stepped for n frames ends in the state `vroc run` records for n frames, the same bits.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "vroc/core/backend.h"

namespace vroc::python {

class Simulation {
public:
    /// `settings`: key=value overrides of the backend's declared settings (InputError lists the
    /// valid keys for an unknown one). `frame_dt` <= 0 means the scene's.
    Simulation(std::shared_ptr<const Scene> scene, const std::string& backend,
               const std::vector<std::pair<std::string, std::string>>& settings, double frame_dt);

    /// Steps `frames` (>= 0) frames of frameDt(). Keeps each frame's events and step wall time.
    void step(std::int64_t frames);
    /// Steps the frames that cover `seconds` (core's frameCount); returns how many.
    std::int64_t run(double seconds);

    double time() const { return backend_->time(); }
    std::int64_t frames() const { return frames_; }
    double frameDt() const { return frame_dt_; }
    const Scene& scene() const { return *scene_; }
    const BackendInfo& info() const { return *info_; }
    const Settings& settings() const { return settings_; }
    int bodyCount() const { return backend_->bodyCount(); }
    BodyState bodyState(int body) const { return backend_->bodyState(body); }

    /// Every body's state (indexed like Scene::bodies) -> the backend. A body whose state equals
    /// its current one bit for bit is left alone (so setStates of the current states changes no bit
    /// and disturbs no cache); other virtual and tracked bodies take theirs through
    /// Backend::setBodyState (a tracked one as a tracker sample), whose own representation may round
    /// the last bit; a real body's must equal its current state: otherwise InputError naming it.
    void setStates(std::span<const BodyState> states);

    /// What restore() needs to bring this simulation back, exactly: the inputs since creation
    /// (states set, impulses applied) at their frames, and the frame count.
    struct Snapshot {
        struct Input {
            std::int64_t frame = 0;            ///< applied before stepping this frame
            std::vector<BodyState> states;     ///< a setStates call, or empty for an impulse
            int body = -1;                     ///< an applyImpulse call
            Vec3 impulse = Vec3::Zero(), point = Vec3::Zero();
        };
        std::vector<Input> inputs;
        std::int64_t frames = 0;
    };
    Snapshot snapshot() const { return {inputs_, frames_}; }
    /// A fresh backend with the same scene and settings, the snapshot's inputs applied at their
    /// frames: the same bits as when the snapshot was taken, on every backend (they are
    /// deterministic), at the cost of stepping the snapshot's frames again. Events and step times
    /// start afresh.
    void restore(const Snapshot& snapshot);
    void applyImpulse(int body, const Vec3& impulse, const Vec3& world_point);

    /// Collision events of the frames stepped since the previous call, in time order.
    std::vector<CollisionEvent> takeEvents();
    WarningCounts warnings() const { return backend_->warnings(); }
    Statistics statistics() const { return backend_->statistics(); }
    std::string stateHash() const;
    /// [s] wall time of every stepFrame call so far.
    const std::vector<double>& stepWallTimes() const { return step_wall_s_; }
    /// [s] steady-clock start and end of the last step() or run() call's stepping.
    std::pair<double, double> lastStepSpan() const { return last_span_; }

private:
    void checkBody(int body, const char* what) const;

    std::shared_ptr<const Scene> scene_;
    const BackendInfo* info_ = nullptr;
    Settings settings_;
    double frame_dt_ = 0;
    std::unique_ptr<Backend> backend_;
    std::int64_t frames_ = 0;
    std::vector<CollisionEvent> events_;
    std::vector<Snapshot::Input> inputs_;
    std::vector<double> step_wall_s_;
    std::pair<double, double> last_span_{0, 0};
};

/// Settings key=value pairs from a backend-relative or full key: "substeps" on bullet is
/// "bullet.substeps"; a key with a '.' is taken as it is.
std::string fullSettingKey(const std::string& backend, const std::string& key);

}  // namespace vroc::python
