// SPDX-License-Identifier: MIT
// Grab and throw through the backend interface only (Backend::setBodyState), so every backend
// sees the same calls. Pressing the grab button takes the nearest virtual body within reach of
// the hand; while held the body keeps its grab-time offset from the hand, with the hand's
// velocities; on release it leaves with the hand's linear and angular velocity estimated by a
// least-squares fit over the last frames.
#pragma once

#include <optional>
#include <vector>

#include "vroc/core/backend.h"
#include "vroc/core/scene.h"
#include "vroc/play/velocity_estimator.h"

namespace vroc::play {

struct GrabSettings {
    double reach = 0.15;        ///< [m] largest hand-to-surface distance (centre distance minus
                                ///< the body's bounding radius) at which a press grabs
    int button = 0;             ///< grab button index
    int velocity_window = 6;    ///< samples in the velocity fit
    int velocity_degree = 2;    ///< polynomial degree of the fit (1 or 2)
};

struct ThrowRecord {
    double time = 0.0;                    ///< [s] simulation time of the release
    int body = -1;                        ///< scene body index
    Vec3 linear_velocity = Vec3::Zero();  ///< [m/s] given to the body's centre (world)
    Vec3 angular_velocity = Vec3::Zero(); ///< [rad/s] world
    Vec3 hand_linear_velocity = Vec3::Zero();   ///< [m/s] estimated hand velocity at release
    bool device_velocity_known = false;         ///< the device reported its own velocities
    Vec3 device_linear_velocity = Vec3::Zero(); ///< [m/s] as the device reported them
    Vec3 device_angular_velocity = Vec3::Zero();///< [rad/s]
};

class GrabController {
public:
    /// Keeps a reference to `scene` (shapes, roles); it must outlive the controller.
    GrabController(const Scene& scene, const GrabSettings& settings);

    /// Call once per frame before Backend::stepFrame, with the hand reading at time t [s].
    void update(double t, const Pose& hand, bool button_down, Backend& backend,
                const Vec3* device_linear = nullptr, const Vec3* device_angular = nullptr);

    std::optional<int> heldBody() const { return held_; }
    const std::vector<ThrowRecord>& throws() const { return throws_; }
    int grabs() const { return grabs_; }

private:
    std::optional<int> nearestBody(const Pose& hand, const Backend& backend) const;
    BodyState heldState(const Pose& hand) const;   // body follows the hand rigidly

    const Scene& scene_;
    GrabSettings settings_;
    VelocityEstimator estimator_;
    bool was_down_ = false;
    std::optional<int> held_;
    Pose offset_;   // body frame -> hand frame, fixed at grab time
    Vec3 com_local_ = Vec3::Zero();   // [m] centre of mass in the body frame
    std::vector<ThrowRecord> throws_;
    int grabs_ = 0;
};

}  // namespace vroc::play
