// SPDX-License-Identifier: MIT
#include "dynamics/rigid_body.h"

#include <Eigen/Eigenvalues>
#include <algorithm>

#include "dynamics/free_flight.h"

namespace vroc::native {

Mat3 RigidBody::invInertiaWorld() const {
    if (infiniteMass()) return Mat3::Zero();
    const Mat3 r = rotation();
    return r * inv_inertia_body * r.transpose();
}

void RigidBody::setAngularVelocity(const Vec3& omega) {
    if (infiniteMass()) return;
    const Mat3 r = rotation();
    angular_momentum = r * inertia_body * r.transpose() * omega;
    refreshEnergy();
}

Vec3 RigidBody::computeAngularVelocity() const {
    // Body-frame form keeps the product cheap and symmetric: omega = R I^-1 R^T L.
    return orientation * (inv_inertia_body * (orientation.conjugate() * angular_momentum));
}

void RigidBody::refreshAngularVelocity() {
    if (infiniteMass()) return;
    omega_ = computeAngularVelocity();
    speed_bound_ = smallestMoment() > 0.0 ? speedBound(omega_) : 0.0;
    omega_orientation_ = orientation.coeffs();
    omega_momentum_ = angular_momentum;
}

Pose RigidBody::framePose() const {
    Pose p;
    p.orientation = orientation;
    p.position = com - orientation * com_offset;
    return p;
}

void RigidBody::applyImpulse(const Vec3& impulse, const Vec3& p) {
    if (infiniteMass()) return;
    velocity += inv_mass * impulse;
    angular_momentum += (p - com).cross(impulse);
    refreshEnergy();
}

void RigidBody::refreshEnergy() {
    refreshAngularVelocity();
    rotational_energy = infiniteMass() ? 0.0 : 0.5 * angular_momentum.dot(angularVelocity());
}

double RigidBody::speedBound(const Vec3& omega) const {
    const double loose = angular_momentum.norm() / smallestMoment();
    if (isotropic) return loose;   // ω is constant: |L| / I is its speed
    const double tight =
        torqueFreeSpeedBound(principal_moments, angular_momentum.squaredNorm(), angular_momentum.dot(omega));
    return tight >= 0.0 ? std::min(tight, loose) : loose;
}

RigidBody RigidBody::fromScene(const Body& body) {
    RigidBody rb;
    rb.is_static = body.isStatic();
    rb.is_kinematic = body.isTracked();
    rb.com_offset = body.isDynamic() ? body.mass_properties.center_of_mass : Vec3::Zero();
    rb.orientation = body.pose.orientation.normalized();
    rb.com = body.pose.position + rb.orientation * rb.com_offset;
    if (rb.is_kinematic) {
        rb.velocity = body.linear_velocity;
        rb.kinematic_angular_velocity = body.angular_velocity;
        rb.isotropic = true;   // ω is constant: the rotation has the closed form
    }
    if (body.isDynamic()) {
        rb.inv_mass = 1.0 / body.mass_properties.mass;
        rb.inertia_body = 0.5 * (body.mass_properties.inertia + body.mass_properties.inertia.transpose());
        rb.inv_inertia_body = rb.inertia_body.inverse();
        Eigen::SelfAdjointEigenSolver<Mat3> eig(rb.inertia_body, Eigen::EigenvaluesOnly);
        rb.principal_moments = eig.eigenvalues();
        rb.isotropic = eig.eigenvalues()(2) - eig.eigenvalues()(0) <= 1e-12 * eig.eigenvalues()(2);
        rb.velocity = body.linear_velocity;
        const Mat3 r = rb.rotation();
        rb.angular_momentum = r * rb.inertia_body * r.transpose() * body.angular_velocity;
    }
    rb.refreshEnergy();
    return rb;
}

void RigidBody::setFromState(const Pose& pose, const Vec3& linear_velocity, const Vec3& angular_velocity) {
    if (is_static) return;
    orientation = pose.orientation.normalized();
    com = pose.position + orientation * com_offset;
    velocity = linear_velocity;
    if (is_kinematic) {
        kinematic_angular_velocity = angular_velocity;
        return;
    }
    setAngularVelocity(angular_velocity);
}

}  // namespace vroc::native
