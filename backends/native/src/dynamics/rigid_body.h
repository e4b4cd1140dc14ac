// SPDX-License-Identifier: MIT
// A rigid body as the native dynamics sees it: state at the centre of mass (COM), world angular
// momentum stored (not angular velocity) so torque-free flight conserves it exactly.
#pragma once

#include <cstring>
#include <limits>

#include "vroc/core/math.h"
#include "vroc/core/scene.h"

namespace vroc::native {

struct RigidBody {
    bool is_static = true;              ///< real bodies: infinite mass, never move
    /// Tracked bodies: infinite mass, moving at prescribed velocities (no gravity, never changed by
    /// an impulse): `velocity` and `kinematic_angular_velocity`, set from the scene or a tracker.
    bool is_kinematic = false;
    Vec3 kinematic_angular_velocity = Vec3::Zero();   ///< [rad/s] world (kinematic bodies only)
    /// No impulse moves it (static or kinematic): it is ground for the solver.
    bool infiniteMass() const { return is_static || is_kinematic; }
    double inv_mass = 0.0;              ///< [1/kg] 0 for static bodies
    Mat3 inertia_body = Mat3::Zero();   ///< [kg m^2] about the COM, body-frame axes
    Mat3 inv_inertia_body = Mat3::Zero();   ///< [1/(kg m^2)] 0 for static bodies
    Vec3 com_offset = Vec3::Zero();     ///< [m] COM in the scene body frame

    Vec3 com = Vec3::Zero();            ///< [m] COM position, world
    Quat orientation = Quat::Identity();   ///< scene body frame -> world (the frame is not moved to the COM)
    Vec3 velocity = Vec3::Zero();       ///< [m/s] COM velocity, world
    Vec3 angular_momentum = Vec3::Zero();  ///< [kg m^2/s] about the COM, world
    double rotational_energy = 0.0;     ///< [J] reference kinetic energy of rotation (set on every impulse)

    /// World rotation matrix of the body frame.
    Mat3 rotation() const { return orientation.toRotationMatrix(); }
    /// [1/(kg m^2)] inverse inertia in world axes (zero for infinite mass).
    Mat3 invInertiaWorld() const;
    /// Sets the angular momentum so that the body turns at `omega` [rad/s, world] (L = I_world omega)
    /// and re-derives the energy reference.
    void setAngularVelocity(const Vec3& omega);
    /// [rad/s] world angular velocity, I_world^-1 L: the value stored by the last refresh while the
    /// orientation and L are bit for bit those it was taken from, else computed afresh (the same bits
    /// either way; a reader never writes, so workers may read one body at once).
    Vec3 angularVelocity() const {
        if (is_static) return Vec3::Zero();
        if (is_kinematic) return kinematic_angular_velocity;
        return omegaStored() ? omega_ : computeAngularVelocity();
    }
    /// Stores ω for the current orientation and L (after either changes: refreshEnergy does it).
    void refreshAngularVelocity();
    /// [m/s] world velocity of the material point at world position `p`.
    Vec3 pointVelocity(const Vec3& p) const { return velocity + angularVelocity().cross(p - com); }
    /// Scene body frame -> world.
    Pose framePose() const;

    /// Applies an impulse [N s] at world point `p` (no effect on infinite mass).
    void applyImpulse(const Vec3& impulse, const Vec3& p);
    /// Re-derives the rotational energy reference after L or the orientation was set from outside.
    void refreshEnergy();
    /// [rad/s] bound on |omega| over torque-free flight: the largest |ω| its energy and |L| allow
    /// (torqueFreeSpeedBound), never more than |L| / smallest principal moment. Stored with ω (the
    /// same bits as computed afresh, under the same key).
    double maxAngularSpeed() const {
        if (is_kinematic) return kinematic_angular_velocity.norm();
        if (is_static || !(smallestMoment() > 0.0)) return 0.0;
        if (omegaStored()) return speed_bound_;
        return speedBound(computeAngularVelocity());
    }
    Vec3 principal_moments = Vec3::Zero();   ///< [kg m^2] ascending (cached at creation)
    /// [kg m^2] the smallest principal moment.
    double smallestMoment() const { return principal_moments(0); }
    /// All principal moments equal (to 1e-12 relative: spheres, cubes): ω = I⁻¹ L is constant in
    /// torque-free flight, so the rotation has a closed form (cached at creation).
    bool isotropic = false;

    static RigidBody fromScene(const Body& body);
    void setFromState(const Pose& pose, const Vec3& linear_velocity, const Vec3& angular_velocity);

private:
    Vec3 computeAngularVelocity() const;
    /// maxAngularSpeed's bound for the body turning at `omega` now.
    double speedBound(const Vec3& omega) const;
    /// The orientation and L are bit for bit those ω was stored from.
    bool omegaStored() const {
        return std::memcmp(omega_orientation_.data(), orientation.coeffs().data(), sizeof(double) * 4) == 0 &&
               std::memcmp(omega_momentum_.data(), angular_momentum.data(), sizeof(double) * 3) == 0;
    }
    // ω and its speed bound as last stored, and the orientation coefficients and L they were taken
    // from (NaN: none yet).
    Vec3 omega_ = Vec3::Zero();
    double speed_bound_ = 0.0;
    Eigen::Vector4d omega_orientation_ = Eigen::Vector4d::Constant(std::numeric_limits<double>::quiet_NaN());
    Vec3 omega_momentum_ = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
};

/// [m/s] how fast B's material point at world `p` approaches A's along `n` (from A to B), the bodies
/// turning at `wa` and `wb` [rad/s] (their angularVelocity(), taken once for many points).
inline double approachAt(const RigidBody& a, const Vec3& wa, const RigidBody& b, const Vec3& wb, const Vec3& p, const Vec3& n) {
    return -((b.velocity + wb.cross(p - b.com)) - (a.velocity + wa.cross(p - a.com))).dot(n);
}

}  // namespace vroc::native
