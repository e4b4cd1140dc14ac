// SPDX-License-Identifier: MIT
#include "ode_backend.h"

#include <cmath>
#include <cstdint>
#include <set>
#include <string>
#include <utility>

#include <Eigen/Cholesky>

#include "ode_convert.h"
#include "ode_runtime.h"
#include "vroc/core/body_motion_checks.h"
#include "vroc/core/errors.h"

namespace vroc::ode {
namespace {

// Everything the constructor relies on, checked before any ODE object exists, so a refused
// scene leaves nothing behind.
const OdeConfig& checked(const Scene& scene, const OdeConfig& config) {
    checkBodiesForEngine(scene, "ode", unsupportedReason);
    return config;
}

std::vector<Material> bodyMaterials(const Scene& scene) {
    std::vector<Material> out;
    for (const Body& body : scene.bodies) out.push_back(scene.materials[static_cast<std::size_t>(body.material)]);
    return out;
}

bool finite(const Vec3& p, const Quat& q, const Vec3& v, const Vec3& w) {
    // A quaternion ODE had to renormalise from an overflow comes back as zero or non-finite.
    const double n = q.norm();
    return p.allFinite() && q.coeffs().allFinite() && n > 0.5 && n < 2.0 && v.allFinite() && w.allFinite();
}

}  // namespace

OdeBackend::OdeBackend(const Scene& scene, const OdeConfig& config)
    : config_(checked(scene, config)),
      shapes_(config_.hull_geom),
      contacts_(bodyMaterials(scene), config_) {
    ensureOdeReady();
    MessageCapture capture(messages_);
    world_.reset(dWorldCreate());
    space_.reset(dHashSpaceCreate(nullptr));
    contact_group_.reset(dJointGroupCreate(0));
    dWorldID w = world_.get();
    dWorldSetGravity(w, scene.gravity.x(), scene.gravity.y(), scene.gravity.z());
    dWorldSetERP(w, config_.erp);
    dWorldSetCFM(w, config_.cfm);
    dWorldSetQuickStepNumIterations(w, config_.quickstep_iterations);
    dWorldSetQuickStepW(w, config_.quickstep_w);
    dWorldSetAutoDisableFlag(w, 0);   // sleeping off (ODE's default too): every body stays simulated
    bodies_.reserve(scene.bodies.size());
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) addBody(static_cast<int>(i), scene.bodies[i]);
}

OdeBackend::~OdeBackend() {
    // Joints before geoms before bodies (members' order): see ode_backend.h.
    if (contact_group_) dJointGroupEmpty(contact_group_.get());
}

void OdeBackend::addBody(int index, const Body& body) {
    BodyRecord rec;
    rec.role = body.role;
    const Quat q = body.pose.orientation.normalized();
    if (body.isStatic()) {
        rec.static_pose = Pose{body.pose.position, q};
        shapes_.place(space_.get(), body.shape, rec.static_pose, index);
        bodies_.push_back(rec);
        return;
    }
    if (body.isTracked()) {
        rec.body = dBodyCreate(world_.get());
        dBodySetKinematic(rec.body);   // ODE's own kinematic body: moved by its velocity, never by forces
        dBodySetGravityMode(rec.body, 0);
        dBodySetAutoDisableFlag(rec.body, 0);
        dBodySetData(rec.body, reinterpret_cast<void*>(static_cast<std::intptr_t>(index)));
        shapes_.attach(space_.get(), rec.body, body.shape, Pose::identity(), index);
        rec.motion.sample.pose = {body.pose.position, q};
        rec.motion.sample.linear_velocity = body.linear_velocity;
        rec.motion.sample.angular_velocity = body.angular_velocity;
        placeTracked(rec, 0.0);
        bodies_.push_back(rec);
        return;
    }
    const MassProperties& mp = body.mass_properties;
    rec.com = mp.center_of_mass;
    rec.mass = mp.mass;
    rec.inertia = 0.5 * (mp.inertia + mp.inertia.transpose());
    rec.body = dBodyCreate(world_.get());
    dMass m;
    dMassSetParameters(&m, rec.mass, 0, 0, 0, rec.inertia(0, 0), rec.inertia(1, 1), rec.inertia(2, 2), rec.inertia(0, 1),
                       rec.inertia(0, 2), rec.inertia(1, 2));
    dBodySetMass(rec.body, &m);
    dBodySetAutoDisableFlag(rec.body, 0);
    dBodySetData(rec.body, reinterpret_cast<void*>(static_cast<std::intptr_t>(index)));
    // Shapes are in the body frame; the ODE frame is the COM frame: shape -> ODE = (-c, identity).
    shapes_.attach(space_.get(), rec.body, body.shape, Pose{-rec.com, Quat::Identity()}, index);
    ComState s;
    s.orientation = q;
    s.position = body.pose.position + q * rec.com;
    s.linear_velocity = body.linear_velocity;
    s.angular_velocity = body.angular_velocity;
    setComState(rec, s);
    rec.last_good = comState(rec);
    bodies_.push_back(rec);
}

void OdeBackend::stepFrame(double dt) {
    if (!(dt > 0.0) || !std::isfinite(dt))
        throw InputError("ode: frame dt must be a positive finite number [s], got " + std::to_string(dt));
    ensureOdeReady();   // this thread may be new to ODE
    MessageCapture capture(messages_);
    const double h = dt / config_.substeps;
    for (int s = 0; s < config_.substeps; ++s) internalStep(h, time_ + (s + 1) * h);
    time_ += dt;
    ++frames_;
}

void OdeBackend::internalStep(double h, double end_time) {
    if (!contacts_current_) contacts_.collide(space_.get());
    broadphase_pairs_ = contacts_.broadphasePairs();
    broadphase_pairs_total_ += broadphase_pairs_;
    const std::vector<ContactPoint>& points = contacts_.points();
    // Sized before any joint points into it: it must not move during the step.
    feedback_.assign(points.size(), dJointFeedback{});
    for (std::size_t i = 0; i < points.size(); ++i) {
        dJointID joint = dJointCreateContact(world_.get(), contact_group_.get(), &points[i].contact);
        dJointAttach(joint, dGeomGetBody(points[i].contact.geom.g1), dGeomGetBody(points[i].contact.geom.g2));
        dJointSetFeedback(joint, &feedback_[i]);
    }
    if (!seededWorldStep(world_.get(), config_.stepper, h, random_seed_)) ++step_failures_;
    ++internal_steps_;
    contact_points_ = points.size();
    contact_points_total_ += contact_points_;

    // f1 is the joint's force on its first (always non-null) body: normal row n*lambda_n plus two
    // friction rows orthogonal to n, so |f1 . n| is the normal force whichever way ODE ordered them.
    std::vector<SolvedContact> solved;
    solved.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        const ContactPoint& p = points[i];
        SolvedContact c;
        c.body_a = p.body_a;
        c.body_b = p.body_b;
        c.point = fromOde(p.contact.geom.pos);
        c.normal_a_to_b = p.normal_a_to_b;
        const double impulse = std::abs(fromOde(feedback_[i].f1).dot(p.normal_a_to_b)) * h;
        c.impulse = std::isfinite(impulse) ? impulse : 0.0;
        solved.push_back(c);
    }
    dJointGroupEmpty(contact_group_.get());
    restoreNonfinite();
    // ODE moved the kinematic bodies by their velocities; put them exactly where the tracker
    // motion has them at the step's end (no drift from the integration of the rotation).
    for (BodyRecord& rec : bodies_)
        if (rec.role == BodyRole::Tracked) placeTracked(rec, end_time);

    // The collision pass at the new poses: the pairs touching now, and the next step's contacts.
    contacts_.collide(space_.get());
    contacts_current_ = true;
    std::set<std::pair<int, int>> touching;
    for (const ContactPoint& p : contacts_.points()) touching.insert({p.body_a, p.body_b});
    events_.afterStep(solved, touching, end_time);
}

// The kinematic body at its motion's pose and velocities. A pose that overflows (a finite but
// huge velocity) is numerical trouble: counted, and the body stays where it was, at rest.
void OdeBackend::placeTracked(BodyRecord& rec, double time) {
    ComState s;
    Pose pose = rec.motion.poseAt(time);
    if (!pose.position.allFinite() || !pose.orientation.coeffs().allFinite()) {
        ++nonfinite_;
        rec.motion.t0 = time;
        rec.motion.sample.pose = Pose{rec.last_good.position, rec.last_good.orientation};
        rec.motion.sample.linear_velocity.setZero();
        rec.motion.sample.angular_velocity.setZero();
        pose = rec.motion.sample.pose;
    }
    s.position = pose.position;
    s.orientation = pose.orientation;
    s.linear_velocity = rec.motion.sample.linear_velocity;
    s.angular_velocity = rec.motion.sample.angular_velocity;
    setComState(rec, s);
    rec.last_good = s;
}

void OdeBackend::restoreNonfinite() {
    for (BodyRecord& rec : bodies_) {
        if (!rec.body || rec.role == BodyRole::Tracked) continue;   // tracked: placeTracked
        const ComState s = comState(rec);
        if (finite(s.position, s.orientation, s.linear_velocity, s.angular_velocity)) {
            rec.last_good = s;
        } else {
            ++nonfinite_;
            setComState(rec, rec.last_good);
        }
    }
}

OdeBackend::ComState OdeBackend::comState(const BodyRecord& rec) const {
    ComState s;
    s.position = fromOde(dBodyGetPosition(rec.body));
    s.orientation = quatFromOde(dBodyGetQuaternion(rec.body));
    s.linear_velocity = fromOde(dBodyGetLinearVel(rec.body));
    s.angular_velocity = fromOde(dBodyGetAngularVel(rec.body));
    return s;
}

void OdeBackend::setComState(BodyRecord& rec, const ComState& s) {
    dBodySetPosition(rec.body, s.position.x(), s.position.y(), s.position.z());
    dQuaternion q;
    toOde(s.orientation, q);
    dBodySetQuaternion(rec.body, q);
    dBodySetLinearVel(rec.body, s.linear_velocity.x(), s.linear_velocity.y(), s.linear_velocity.z());
    dBodySetAngularVel(rec.body, s.angular_velocity.x(), s.angular_velocity.y(), s.angular_velocity.z());
    dBodySetForce(rec.body, 0, 0, 0);
    dBodySetTorque(rec.body, 0, 0, 0);
}

OdeBackend::BodyRecord& OdeBackend::record(int body, const char* what) {
    if (body < 0 || body >= bodyCount())
        throw InputError(std::string("ode: ") + what + ": no body with index " + std::to_string(body) + " (" +
                         std::to_string(bodyCount()) + " bodies)");
    return bodies_[static_cast<std::size_t>(body)];
}

BodyState OdeBackend::bodyState(int body) const {
    if (body < 0 || body >= bodyCount())
        throw InputError("ode: bodyState: no body with index " + std::to_string(body) + " (" +
                         std::to_string(bodyCount()) + " bodies)");
    const BodyRecord& rec = bodies_[static_cast<std::size_t>(body)];
    BodyState out;
    if (!rec.body) {
        out.pose = rec.static_pose;
        return out;
    }
    const ComState s = comState(rec);
    out.pose.orientation = s.orientation;
    out.pose.position = s.position - s.orientation * rec.com;   // the scene's body frame origin
    out.linear_velocity = s.linear_velocity;
    out.angular_velocity = s.angular_velocity;
    return out;
}

void OdeBackend::setBodyState(int body, const BodyState& state) {
    BodyRecord& rec = record(body, "setBodyState");
    if (!rec.body) return;   // real bodies do not move
    const Quat& q = state.pose.orientation;
    if (!state.pose.position.allFinite() || !q.coeffs().allFinite() || !state.linear_velocity.allFinite() ||
        !state.angular_velocity.allFinite()) {
        ++nonfinite_;   // a tracker glitch: counted and refused, the body unchanged
        return;
    }
    if (q.norm() == 0.0)
        throw InputError("ode: setBodyState: body " + std::to_string(body) + ": expected a non-zero quaternion");
    if (rec.role == BodyRole::Tracked) {   // a tracker sample: this pose now, these velocities from now on
        rec.motion.t0 = time_;
        rec.motion.sample = BodyState{Pose{state.pose.position, q.normalized()}, state.linear_velocity,
                                      state.angular_velocity};
        placeTracked(rec, time_);
        contacts_current_ = false;
        return;
    }
    ComState s;
    s.orientation = q.normalized();
    s.position = state.pose.position + s.orientation * rec.com;
    s.linear_velocity = state.linear_velocity;
    s.angular_velocity = state.angular_velocity;
    setComState(rec, s);
    rec.last_good = comState(rec);
    contacts_current_ = false;   // the geoms moved: the next step collides afresh
}

void OdeBackend::applyImpulse(int body, const Vec3& impulse, const Vec3& world_point) {
    BodyRecord& rec = record(body, "applyImpulse");
    if (rec.role != BodyRole::Virtual) return;   // real and tracked bodies have infinite mass
    if (!impulse.allFinite() || !world_point.allFinite()) {
        ++nonfinite_;   // counted and ignored
        return;
    }
    // Directly as a velocity change (dBodyAddForce would act over the next step, under contacts):
    // dv = J / m, dw = I_world^-1 ((p - com) x J).
    ComState s = comState(rec);
    const Mat3 R = s.orientation.toRotationMatrix();
    const Mat3 inertia_world = R * rec.inertia * R.transpose();
    s.linear_velocity += impulse / rec.mass;
    s.angular_velocity += inertia_world.ldlt().solve((world_point - s.position).cross(impulse));
    dBodySetLinearVel(rec.body, s.linear_velocity.x(), s.linear_velocity.y(), s.linear_velocity.z());
    dBodySetAngularVel(rec.body, s.angular_velocity.x(), s.angular_velocity.y(), s.angular_velocity.z());
}

WarningCounts OdeBackend::warnings() const {
    return {{"nonfinite_state", nonfinite_},
            {"ill_conditioned_solve", messages_.lcp},   // Dantzig LCP stopped early on a near-singular system
            {"ode.messages", messages_.other},
            {"ode.step_failed", step_failures_}};
}

Statistics OdeBackend::statistics() const {
    const double steps = static_cast<double>(internal_steps_);
    auto mean = [&](std::uint64_t total) { return steps > 0 ? static_cast<double>(total) / steps : 0.0; };
    return {
        {"frames", static_cast<double>(frames_)},
        {"internal_steps", steps},
        {"collision_events", static_cast<double>(events_.eventTotal())},
        {"contact_points", static_cast<double>(contact_points_)},
        {"contact_points_mean", mean(contact_points_total_)},
        {"broadphase_pairs", static_cast<double>(broadphase_pairs_)},
        {"broadphase_pairs_mean", mean(broadphase_pairs_total_)},
        {"ode.pairs_in_contact", static_cast<double>(events_.pairsInContact())},
    };
}

}  // namespace vroc::ode
