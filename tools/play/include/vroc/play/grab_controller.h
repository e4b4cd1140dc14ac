// SPDX-License-Identifier: MIT
// Grab and throw as a virtual coupling (Colgate, Stanley & Brown 1995): while a body is held, a
// spring-damper joins it to the hand, and the loop feeds the coupling's force to the backend as
// impulses (Backend::applyImpulse only, so every backend sees the same calls) and its reaction to
// the hand device (force output). The body stays a dynamic body throughout: the backend's contacts
// stop it at a real surface while the hand goes on, and the force grows with the distance between
// them. Pressing the grab button takes the nearest virtual body within reach; on release the body
// simply keeps the velocity it has (a throw).
#pragma once

#include <optional>
#include <vector>

#include "vroc/core/backend.h"
#include "vroc/core/scene.h"
#include "vroc/play/velocity_estimator.h"

namespace vroc::play {

/// Grab and coupling settings. The coupling is a critically damped spring-damper scaled by the
/// held body's mass and inertia, so every body follows the hand with the same dynamics:
///   F = k (x_target - x_body) + c (v_target - v_body),      k = m w^2,  c = 2 zeta m w
///   T = I_world (w^2 theta + 2 zeta w (w_hand - w_body)),   theta = rotation vector of q_target q_body^-1
/// with w = 2 pi coupling_frequency [rad/s]. It is applied explicitly, once per frame of dt, as the
/// impulse F dt (and T dt as a couple). Per axis that is the recurrence
///   v' = v + (a/dt) e + b (v_target - v),  x' = x + v' dt,  a = (w dt)^2, b = 2 zeta w dt,
/// whose characteristic polynomial z^2 - (2 - a - b) z + (1 - b) has both roots inside the unit
/// circle iff b < 2 and a + 2b < 4. At 5 Hz and 60 frames/s: w dt = 0.52, a = k dt^2/m = 0.27 (the
/// undamped limit is 4), a + 2b = 2.37; the slow root is 0.74 per frame (time constant 56 ms).
struct GrabSettings {
    double reach = 0.15;        ///< [m] largest hand-to-surface distance (centre distance minus
                                ///< the body's bounding radius) at which a press grabs
    int button = 0;             ///< grab button index
    int velocity_window = 6;    ///< samples in the hand's velocity fit
    int velocity_degree = 2;    ///< polynomial degree of the fit (1 or 2)
    /// [Hz] natural frequency of the coupling. 5 Hz: stiff enough that a hand swing (30 m/s^2)
    /// leads the body by only a^2/w^2 = 3 cm, soft enough to be far inside the explicit scheme's
    /// stability region at 60 frames/s (see above); a 1 kg body gets k = 987 N/m.
    double coupling_frequency = 5.0;
    /// [-] damping ratio zeta. 1 (critical): the body settles on the hand without overshoot, so a
    /// body pushed at a wall comes to rest on it instead of bouncing.
    double coupling_damping_ratio = 1.0;
    /// [-] w dt is capped at this fraction of the stability limit x_max = 2 (sqrt(zeta^2 + 1) - zeta)
    /// (0.83 at zeta = 1), so long frames soften the coupling instead of making it diverge. Not
    /// reached at the defaults and 60 frames/s (w dt = 0.52 < 0.58).
    double coupling_stability_fraction = 0.7;
    /// Add the impulse -m g dt to the held body each frame so it hangs at the hand rather than
    /// sagging by m g / k = g / w^2 (10 mm at 5 Hz). The weight is then not part of the force the
    /// hand feels (only the coupling's reaction is sent).
    bool gravity_compensation = true;
};

struct ThrowRecord {
    double time = 0.0;                    ///< [s] simulation time of the release
    int body = -1;                        ///< scene body index
    Vec3 linear_velocity = Vec3::Zero();  ///< [m/s] of the body's centre of mass at release (world)
    Vec3 angular_velocity = Vec3::Zero(); ///< [rad/s] world
    Vec3 hand_linear_velocity = Vec3::Zero();   ///< [m/s] estimated hand velocity at release
    bool device_velocity_known = false;         ///< the device reported its own velocities
    Vec3 device_linear_velocity = Vec3::Zero(); ///< [m/s] as the device reported them
    Vec3 device_angular_velocity = Vec3::Zero();///< [rad/s]
};

/// The coupling's reaction on the hand in the frame just updated, to send to a force-output device.
struct HandWrench {
    bool active = false;           ///< a body was held and coupled this frame
    Vec3 force = Vec3::Zero();     ///< [N] world: -F
    Vec3 torque = Vec3::Zero();    ///< [N m] world, about the hand's sensor origin: -T + r x (-F),
                                   ///< r = target point of the body's centre of mass - hand position
};

/// One frame's hand reading for GrabController::update.
struct HandInput {
    double t = 0.0;                 ///< [s] simulation time of the frame about to be stepped
    double dt = 0.0;                ///< [s] that frame's step (> 0)
    Pose pose;                      ///< hand sensor -> world
    bool button = false;            ///< the grab button is held
    std::optional<double> sample_time;   ///< [s, simulation clock] when the pose was measured, for the
                                         ///< hand's velocity fit (a live device's samples come at its own
                                         ///< rate); default t
    std::optional<Vec3> device_linear;   ///< [m/s] the device's own velocities, if it gives them
    std::optional<Vec3> device_angular;  ///< [rad/s] (recorded with a throw)
};

/// The held body's coupling gains at the last update's dt.
struct CouplingGains {
    double omega = 0.0;            ///< [rad/s] natural frequency used (after the stability cap)
    double stiffness = 0.0;        ///< [N/m] k = m w^2
    double damping = 0.0;          ///< [N s/m] c = 2 zeta m w
};

class GrabController {
public:
    /// Keeps a reference to `scene` (shapes, roles, mass properties, gravity); it must outlive the
    /// controller. Throws std::invalid_argument for settings out of range.
    GrabController(const Scene& scene, const GrabSettings& settings);

    /// Call once per frame before Backend::stepFrame(hand.dt). Grabs on a press, couples the held
    /// body (impulses through `backend`), releases on a release.
    void update(const HandInput& hand, Backend& backend);

    std::optional<int> heldBody() const { return held_; }
    const std::vector<ThrowRecord>& throws() const { return throws_; }
    int grabs() const { return grabs_; }
    const HandWrench& handWrench() const { return wrench_; }
    const CouplingGains& gains() const { return gains_; }
    /// [rad/s] the natural frequency used for a frame of dt (2 pi f, capped for stability).
    double couplingOmega(double dt) const;

private:
    std::optional<int> nearestBody(const Pose& hand, const Backend& backend) const;
    void couple(const HandInput& hand, const BodyState& body, Backend& backend);

    const Scene& scene_;
    GrabSettings settings_;
    VelocityEstimator estimator_;
    bool was_down_ = false;
    std::optional<int> held_;
    Pose offset_;                     // body frame -> hand frame, fixed at grab time
    Vec3 com_local_ = Vec3::Zero();   // [m] centre of mass in the body frame
    double mass_ = 0.0;               // [kg]
    Mat3 inertia_ = Mat3::Zero();     // [kg m^2] about the centre of mass, body axes
    std::optional<Vec3> last_com_;    // [m] held body's centre of mass at the previous update
    double last_t_ = 0.0;             // [s] time of last_com_
    std::vector<ThrowRecord> throws_;
    int grabs_ = 0;
    HandWrench wrench_;
    CouplingGains gains_;
};

}  // namespace vroc::play
