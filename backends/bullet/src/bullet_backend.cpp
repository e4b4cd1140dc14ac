// SPDX-License-Identifier: MIT
#include "bullet_backend.h"
#include "vroc/core/backend_vocabulary.h"

#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <string>

#include "bullet_convert.h"
#include "material_combine.h"
#include "principal_frame.h"
#include "vroc/core/body_motion_checks.h"
#include "vroc/core/errors.h"

namespace vroc::bullet {
namespace {

bool finite(const btTransform& t, const btVector3& v, const btVector3& w) {
    const btMatrix3x3& m = t.getBasis();
    return fromBt(t.getOrigin()).allFinite() && fromBt(m[0]).allFinite() && fromBt(m[1]).allFinite() &&
           fromBt(m[2]).allFinite() && fromBt(v).allFinite() && fromBt(w).allFinite();
}

// Everything addBody() relies on, checked before any body enters the world (a throw half-way
// would leave Bullet holding bodies that are being destroyed).
void validate(const Scene& scene) {
    for (const Body& body : scene.bodies) {
        if (body.material < 0 || static_cast<std::size_t>(body.material) >= scene.materials.size())
            throw InputError("scene '" + scene.name + "': body '" + body.name + "': material index " +
                             std::to_string(body.material) + " out of range");
        if (body.isTracked() && !hasFiniteMotion(body))
            throw InputError("scene '" + scene.name + "': body '" + body.name +
                             "': a tracked body needs a finite pose (non-zero quaternion) and finite velocities");
        if (!body.isDynamic()) continue;
        if (!(body.mass_properties.mass > 0.0) || !(principalFrame(body.mass_properties).principal_inertia.minCoeff() > 0.0))
            throw InputError("scene '" + scene.name + "': body '" + body.name +
                             "': a virtual body needs positive mass and positive principal inertia");
    }
}

}  // namespace

BulletBackend::BulletBackend(const Scene& scene, const BulletConfig& config)
    : config_(config),
      gravity_(scene.gravity),
      collision_config_(std::make_unique<btDefaultCollisionConfiguration>()),
      dispatcher_(std::make_unique<btCollisionDispatcher>(collision_config_.get())),
      broadphase_(std::make_unique<btDbvtBroadphase>()),
      solver_(std::make_unique<btSequentialImpulseConstraintSolver>()),
      world_(std::make_unique<btDiscreteDynamicsWorld>(dispatcher_.get(), broadphase_.get(), solver_.get(),
                                                       collision_config_.get())),
      shapes_(ShapeOptions{config.margin, config.shrink_hulls}),
      events_(scene.collision_distance) {
    validate(scene);
    installMaterialCombineCallbacks();
    world_->setGravity(toBt(scene.gravity));
    world_->setInternalTickCallback(&BulletBackend::preTick, this, /*isPreTick=*/true);
    configureSolver();
    bodies_.reserve(scene.bodies.size());
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        const Body& body = scene.bodies[i];
        addBody(static_cast<int>(i), body);
        auto& rigid = *bodies_.back().rigid;
        rigid.setRestitution(scene.materials.at(static_cast<std::size_t>(body.material)).restitution);
        rigid.setFriction(scene.materials.at(static_cast<std::size_t>(body.material)).friction);
    }
}

BulletBackend::~BulletBackend() {
    for (auto& b : bodies_) world_->removeRigidBody(b.rigid.get());
}

void BulletBackend::configureSolver() {
    btContactSolverInfo& info = world_->getSolverInfo();
    info.m_numIterations = config_.solver_iterations;
    info.m_splitImpulse = config_.split_impulse ? 1 : 0;
    info.m_restitutionVelocityThreshold = config_.restitution_threshold;
    info.m_warmstartingFactor = config_.warmstarting_factor;
    // Bullet 3.24's default mode (SOLVER_USE_WARMSTARTING | SOLVER_SIMD, btContactSolverInfo.h) puts
    // one friction row per point along the sliding velocity; the flag adds a second row along
    // dir1 x normal (btSequentialImpulseConstraintSolver::convertContact), each clamped to mu N.
    if (config_.friction_directions == 2) info.m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS;
}

void BulletBackend::addBody(int index, const Body& body) {
    BodyRecord rec;
    rec.role = body.role;
    double mass = 0.0;   // static and kinematic bodies: infinite mass
    btVector3 inertia(0, 0, 0);
    if (body.isDynamic()) {
        const PrincipalFrame pf = principalFrame(body.mass_properties);   // validated
        rec.com_in_body = pf.body_to_com;
        mass = body.mass_properties.mass;
        inertia = toBt(pf.principal_inertia);
    }
    btCollisionShape* shape = shapes_.map(body.shape, rec.com_in_body);
    btRigidBody::btRigidBodyConstructionInfo ci(mass, nullptr, shape, inertia);
    rec.rigid = std::make_unique<btRigidBody>(ci);
    btRigidBody& rigid = *rec.rigid;
    rigid.setUserIndex(index);
    rigid.setWorldTransform(toBt(body.pose * rec.com_in_body));
    rigid.setInterpolationWorldTransform(rigid.getWorldTransform());
    if (body.isTracked()) {
        // Bullet's kinematic body: moved by the program, never by the solver, which sees its
        // velocity; addRigidBody puts it in StaticFilter, so it meets no static or kinematic body.
        rigid.setCollisionFlags(rigid.getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
        rigid.setActivationState(DISABLE_DEACTIVATION);
        rec.motion.sample.pose = {body.pose.position, body.pose.orientation.normalized()};
        rec.motion.sample.linear_velocity = body.linear_velocity;
        rec.motion.sample.angular_velocity = body.angular_velocity;
        tracked_.push_back(index);
    } else if (body.isDynamic()) {
        rigid.setActivationState(DISABLE_DEACTIVATION);   // sleeping off: no frozen bodies
        rigid.setLinearVelocity(toBt(body.linear_velocity));
        rigid.setAngularVelocity(toBt(body.angular_velocity));
        rigid.setInterpolationLinearVelocity(rigid.getLinearVelocity());
        rigid.setInterpolationAngularVelocity(rigid.getAngularVelocity());
        if (config_.ccd) {
            // Swept-sphere CCD when a step moves the COM further than the inner radius; the swept
            // sphere (bullet.ccd_radius of the inner radius) stays inside the shape.
            const double r = innerRadius(body.shape);
            rigid.setCcdMotionThreshold(r);
            rigid.setCcdSweptSphereRadius(config_.ccd_radius * r);
            ++ccd_bodies_;
        }
    }
    world_->addRigidBody(&rigid);
    if (body.isDynamic()) rigid.setGravity(toBt(gravity_));
    if (body.isTracked()) placeTracked(rec, 0.0);
    rec.last_good = comState(rigid);
    bodies_.push_back(std::move(rec));
}

void BulletBackend::stepFrame(double dt) {
    if (!(dt > 0.0) || !std::isfinite(dt)) throw InputError("bullet: frame dt must be a positive number, got " + std::to_string(dt));
    const double h = dt / config_.substeps;
    for (int s = 0; s < config_.substeps; ++s) internalStep(h, time_ + (s + 1) * h);
    time_ += dt;
    ++frames_;
}

void BulletBackend::internalStep(double h, double end_time) {
    // maxSubSteps = 0: exactly one internal step of h, no interpolation of reported states.
    world_->stepSimulation(h, 0, h);
    ++internal_steps_;
    recoverBadStates();
    events_.afterStep(*dispatcher_, end_time);
    // Tracked bodies to where they are at the step's end, which is the next step's start: every
    // step collides the bodies at one time, and the frame's last step leaves them at the frame end.
    for (int i : tracked_) placeTracked(bodies_[static_cast<std::size_t>(i)], end_time);
}

// The kinematic body at its motion's pose. A pose that overflows (a finite but huge velocity) is
// numerical trouble: counted, and the body stays where it was, at rest, from then on.
void BulletBackend::placeTracked(BodyRecord& rec, double time) {
    Pose pose = rec.motion.poseAt(time);
    if (!pose.position.allFinite() || !pose.orientation.coeffs().allFinite()) {
        ++nonfinite_;
        rec.motion.t0 = time;
        rec.motion.sample.pose = fromBt(rec.rigid->getWorldTransform());
        rec.motion.sample.linear_velocity.setZero();
        rec.motion.sample.angular_velocity.setZero();
        pose = rec.motion.sample.pose;
    }
    btRigidBody& rigid = *rec.rigid;
    rigid.setWorldTransform(toBt(pose));
    // Interpolation transform = world transform: Bullet's saveKinematicState then estimates a zero
    // velocity, which preTick replaces by the tracker's.
    rigid.setInterpolationWorldTransform(rigid.getWorldTransform());
    rigid.setLinearVelocity(toBt(rec.motion.sample.linear_velocity));
    rigid.setAngularVelocity(toBt(rec.motion.sample.angular_velocity));
    rigid.setInterpolationLinearVelocity(rigid.getLinearVelocity());
    rigid.setInterpolationAngularVelocity(rigid.getAngularVelocity());
}

// stepSimulation sets a kinematic body's velocity by finite differences of its transforms
// (btRigidBody::saveKinematicState) before the internal step; the step then calls this, so the
// contact solver sees the tracker's velocities exactly (the difference quotient of a small turn
// loses digits in acos).
void BulletBackend::preTick(btDynamicsWorld* world, double /*h*/) {
    static_cast<BulletBackend*>(world->getWorldUserInfo())->holdTrackedVelocities();
}

void BulletBackend::holdTrackedVelocities() {
    for (int i : tracked_) {
        const BodyRecord& rec = bodies_[static_cast<std::size_t>(i)];
        rec.rigid->setLinearVelocity(toBt(rec.motion.sample.linear_velocity));
        rec.rigid->setAngularVelocity(toBt(rec.motion.sample.angular_velocity));
    }
}

// Two kinds of trouble, each counted and recovered so the run goes on:
//  - a non-finite state: the body goes back to its last good state;
//  - Bullet's AABB overflow (coordinates too large for its bounds arithmetic): Bullet silently
//    stops simulating the body; it goes back to its last good pose, at rest, and is simulated.
void BulletBackend::recoverBadStates() {
    for (auto& rec : bodies_) {
        if (rec.role != BodyRole::Virtual) continue;   // tracked bodies: placeTracked
        btRigidBody& rigid = *rec.rigid;
        if (!finite(rigid.getWorldTransform(), rigid.getLinearVelocity(), rigid.getAngularVelocity())) {
            ++nonfinite_;
            setComState(rigid, rec.last_good);
        } else if (rigid.getActivationState() == DISABLE_SIMULATION) {
            ++aabb_overflow_;
            BodyState at_rest = rec.last_good;
            at_rest.linear_velocity.setZero();
            at_rest.angular_velocity.setZero();
            setComState(rigid, at_rest);
        } else {
            rec.last_good = comState(rigid);
        }
    }
}

BodyState BulletBackend::comState(const btRigidBody& rigid) const {
    BodyState s;
    s.pose = fromBt(rigid.getWorldTransform());
    s.linear_velocity = fromBt(rigid.getLinearVelocity());
    s.angular_velocity = fromBt(rigid.getAngularVelocity());
    return s;
}

void BulletBackend::setComState(btRigidBody& rigid, const BodyState& com) {
    rigid.setWorldTransform(toBt(com.pose));
    rigid.setInterpolationWorldTransform(rigid.getWorldTransform());
    rigid.setLinearVelocity(toBt(com.linear_velocity));
    rigid.setAngularVelocity(toBt(com.angular_velocity));
    rigid.setInterpolationLinearVelocity(rigid.getLinearVelocity());
    rigid.setInterpolationAngularVelocity(rigid.getAngularVelocity());
    rigid.updateInertiaTensor();
    rigid.clearForces();
    // Bullet disables simulation of a body whose AABB overflowed; sleeping stays off.
    rigid.forceActivationState(DISABLE_DEACTIVATION);
}

BodyState BulletBackend::bodyState(int body) const {
    if (body < 0 || body >= bodyCount()) throw InputError("bullet: no body with index " + std::to_string(body));
    const BodyRecord& rec = bodies_[static_cast<std::size_t>(body)];
    BodyState s = comState(*rec.rigid);
    if (rec.role == BodyRole::Tracked) {   // the tracker's velocities, not Bullet's estimate
        s.linear_velocity = rec.motion.sample.linear_velocity;
        s.angular_velocity = rec.motion.sample.angular_velocity;
    }
    s.pose = s.pose * rec.com_in_body.inverse();   // report the scene's body frame
    if (s.pose.orientation.w() < 0.0) s.pose.orientation.coeffs() *= -1.0;   // same rotation, w >= 0
    return s;
}

BulletBackend::BodyRecord& BulletBackend::record(int body, const char* what) {
    if (body < 0 || body >= bodyCount())
        throw InputError(std::string("bullet: ") + what + ": no body with index " + std::to_string(body));
    return bodies_[static_cast<std::size_t>(body)];
}

void BulletBackend::setBodyState(int body, const BodyState& state) {
    BodyRecord& rec = record(body, "setBodyState");
    if (rec.role == BodyRole::Real) return;
    // A non-finite state is numerical trouble (a tracker glitch): counted and refused. A zero
    // quaternion is no rotation at all: the caller's mistake.
    if (!state.pose.position.allFinite() || !state.pose.orientation.coeffs().allFinite() ||
        !state.linear_velocity.allFinite() || !state.angular_velocity.allFinite()) {
        ++nonfinite_;
        return;
    }
    if (state.pose.orientation.norm() == 0.0)
        throw InputError("bullet: setBodyState: body " + std::to_string(body) + ": expected a non-zero quaternion");
    BodyState com = state;
    com.pose.orientation.normalize();
    if (rec.role == BodyRole::Tracked) {   // a tracker sample: this pose now, these velocities from now on
        rec.motion.t0 = time_;
        rec.motion.sample = com;
        placeTracked(rec, time_);
        return;
    }
    com.pose = com.pose * rec.com_in_body;
    setComState(*rec.rigid, com);
}

void BulletBackend::applyImpulse(int body, const Vec3& impulse, const Vec3& world_point) {
    BodyRecord& rec = record(body, "applyImpulse");
    if (rec.role != BodyRole::Virtual) return;   // real and tracked bodies have infinite mass
    if (!impulse.allFinite() || !world_point.allFinite()) {   // numerical trouble: counted, ignored
        ++nonfinite_;
        return;
    }
    btRigidBody& rigid = *rec.rigid;
    rigid.updateInertiaTensor();   // world inverse inertia for the current orientation
    rigid.applyImpulse(toBt(impulse), toBt(world_point) - rigid.getWorldTransform().getOrigin());
    rigid.activate(true);
}

WarningCounts BulletBackend::warnings() const {
    return vocabulary::prefixed(WarningCounts{{"nonfinite_state", nonfinite_}, {"aabb_overflow", aabb_overflow_}}, "bullet");
}

Statistics BulletBackend::statistics() const {
    const double steps = static_cast<double>(internal_steps_);
    return vocabulary::prefixed(Statistics{
        {"frames", static_cast<double>(frames_)},
        {"internal_steps", steps},
        {"ccd_bodies", static_cast<double>(ccd_bodies_)},
        {"broadphase_pairs", static_cast<double>(broadphase_->getOverlappingPairCache()->getNumOverlappingPairs())},
        {"manifolds", static_cast<double>(events_.manifoldCount())},
        {"contact_points", static_cast<double>(events_.contactPointCount())},
        {"contact_points_mean", steps > 0 ? static_cast<double>(events_.contactPointTotal()) / steps : 0.0},
        {"pairs_in_contact", static_cast<double>(events_.pairsInContact())},
        {"collision_events", static_cast<double>(events_.eventTotal())},
    }, "bullet");
}

}  // namespace vroc::bullet
