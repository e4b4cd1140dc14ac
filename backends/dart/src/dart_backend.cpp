// SPDX-License-Identifier: MIT
#include "dart_backend.h"

#include <cmath>
#include <dart/collision/CollisionObject.hpp>
#include <dart/collision/fcl/FCLCollisionDetector.hpp>
#include <dart/constraint/BoxedLcpConstraintSolver.hpp>
#include <dart/constraint/ConstraintSolver.hpp>
#include <dart/dynamics/Frame.hpp>
#include <dart/dynamics/Inertia.hpp>
#include <iostream>
#include <set>
#include <string>
#include <utility>

#include <Eigen/Cholesky>

#include "shape_mapping.h"
#include "vroc/core/body_motion_checks.h"
#include "vroc/core/errors.h"

namespace vroc::dart {
namespace {

namespace dd = ::dart::dynamics;

// Everything the constructor relies on, checked before any DART object exists, so a refused
// scene leaves nothing behind.
const DartConfig& checked(const Scene& scene, const DartConfig& config) {
    checkBodiesForEngine(scene, "dart", unsupportedReason);
    return config;
}

// Debian's libdart is built with its assertions on: a NaN that appears inside World::step (a bias
// force from an angular velocity whose square overflows, say) aborts the process. So a state is
// handed to DART only if it is finite with every coordinate below this bound, far beyond any
// physical scene yet far enough below the overflow of the squares DART forms.
constexpr double kStateLimit = 1e100;  // [m], [m/s], [rad/s]

bool bounded(const Vec3& x) { return x.allFinite() && x.cwiseAbs().maxCoeff() < kStateLimit; }

bool steppable(const Vec3& p, const Quat& q, const Vec3& v, const Vec3& w) {
    const double n = q.norm();
    return bounded(p) && q.coeffs().allFinite() && n > 0.5 && n < 2.0 && bounded(v) && bounded(w);
}

Eigen::Isometry3d isometry(const Pose& pose) {
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.linear() = pose.orientation.normalized().toRotationMatrix();
    t.translation() = pose.position;
    return t;
}

// Whether any body (or compound part) of the scene has this shape kind.
bool sceneHas(const Scene& scene, Shape::Kind kind) {
    for (const Body& b : scene.bodies) {
        if (b.shape.kind == kind) return true;
        for (const ShapePart& p : b.shape.parts)
            if (p.shape.kind == kind) return true;
    }
    return false;
}

}  // namespace

DartBackend::DartBackend(const Scene& scene, const DartConfig& config)
    : config_(checked(scene, config)), filter_(std::make_shared<ClassFilter>()) {
    world_ = ::dart::simulation::World::create("vroc");
    world_->setGravity(scene.gravity);
    world_->setTimeStep(scene.frame_dt / static_cast<double>(config_.stepsFor(scene.frame_dt)));
    auto* solver = world_->getConstraintSolver();
    // Before any shape reaches the collision group: FCL geometries are made when shapes join it.
    auto fcl = std::dynamic_pointer_cast<::dart::collision::FCLCollisionDetector>(solver->getCollisionDetector());
    // FCL's own sphere misses DART's triangle-mesh hulls (measured: a ball dropped on a static hull
    // falls through it, and the staircase's balls through every step), so a scene with spheres and
    // hulls keeps DART 6.12's mesh collision, where both are meshes and the contact is found.
    mesh_for_hulls_ = sceneHas(scene, Shape::Kind::Sphere) && sceneHas(scene, Shape::Kind::Hull);
    if (fcl && config_.primitive_shapes == PrimitiveShapes::Primitive && !mesh_for_hulls_) {
        // DART 6.12 prints a warning (to std::cerr) whenever PRIMITIVE is chosen, once per backend:
        // the choice is documented (docs/dart-backend.md), so the line is kept off the run's output.
        std::streambuf* err = std::cerr.rdbuf(nullptr);
        fcl->setPrimitiveShapeType(::dart::collision::FCLCollisionDetector::PRIMITIVE);
        std::cerr.rdbuf(err);
    }
    auto* boxed = dynamic_cast<::dart::constraint::BoxedLcpConstraintSolver*>(solver);
    if (boxed) {
        lcp_ = std::make_shared<SizedBoxedLcpSolver>(config_.dantzig_max_rows);
        boxed->setBoxedLcpSolver(lcp_);
    }
    ::dart::collision::CollisionOption& option = solver->getCollisionOption();
    option.collisionFilter = filter_;
    if (config_.max_contacts > 0) contact_capacity_ = static_cast<std::size_t>(config_.max_contacts);
    option.maxNumContacts = contact_capacity_;
    const MaterialClasses classes(scene);
    bodies_.reserve(scene.bodies.size());
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) addBody(static_cast<int>(i), scene.bodies[i], classes);
}

DartBackend::~DartBackend() {
    // The world holds the filter through its collision option; drop the skeletons first.
    if (world_) world_->removeAllSkeletons();
}

void DartBackend::addBody(int index, const Body& body, const MaterialClasses& classes) {
    BodyRecord rec;
    rec.role = body.role;
    rec.skeleton = dd::Skeleton::create("body" + std::to_string(index));
    auto [joint, node] = rec.skeleton->createJointAndBodyNodePair<dd::FreeJoint>();
    rec.joint = joint;
    rec.node = node;
    const Quat q = body.pose.orientation.normalized();
    FrameState s;
    s.orientation = q;
    if (body.isDynamic()) {
        const MassProperties& mp = body.mass_properties;
        rec.com = mp.center_of_mass;
        rec.mass = mp.mass;
        rec.inertia = 0.5 * (mp.inertia + mp.inertia.transpose());
        node->setInertia(dd::Inertia(rec.mass, Eigen::Vector3d::Zero(), rec.inertia));
        s.position = body.pose.position + q * rec.com;
        s.linear_velocity = body.linear_velocity;  // of the centre of mass, as the scene gives it
        s.angular_velocity = body.angular_velocity;
        if (!bounded(s.linear_velocity) || !bounded(s.angular_velocity)) {
            ++nonfinite_;  // a speed DART cannot step: counted, the body starts at rest
            s.linear_velocity.setZero();
            s.angular_velocity.setZero();
        }
    } else {
        s.position = body.pose.position;
    }
    // Shapes are in the body frame; the DART frame is the COM frame: shape -> DART = (-c, identity).
    addShapes(rec, body, Pose{-rec.com, Quat::Identity()}, classes, index);
    if (body.isTracked()) {
        joint->setActuatorType(dd::Joint::VELOCITY);  // DART's prescribed motion: not reactive
        node->setGravityMode(false);
        rec.motion.sample.pose = {body.pose.position, q};
        rec.motion.sample.linear_velocity = body.linear_velocity;
        rec.motion.sample.angular_velocity = body.angular_velocity;
    }
    if (body.isStatic()) rec.static_pose = Pose{body.pose.position, q};
    setFrameState(rec, s);
    if (body.isTracked()) placeTracked(rec, 0.0);
    if (body.isStatic()) rec.skeleton->setMobile(false);
    rec.last_good = frameState(rec);
    world_->addSkeleton(rec.skeleton);
    bodies_.push_back(std::move(rec));
}

// One shape set per material class the body may touch (contact_classes.h).
void DartBackend::addShapes(BodyRecord& rec, const Body& body, const Pose& shape_frame_in_dart,
                            const MaterialClasses& classes, int index) {
    const int own = classes.classOf(index);
    for (int partner = 0; partner < classes.count(); ++partner) {
        for (const PlacedShape& placed : dartShapes(body.shape)) {
            dd::ShapeNode* sn = rec.node->createShapeNodeWith<dd::CollisionAspect, dd::DynamicsAspect>(placed.shape);
            sn->setRelativeTransform(isometry(shape_frame_in_dart * placed.pose));
            dd::DynamicsAspect* dynamics = sn->getDynamicsAspect();
            dynamics->setFrictionCoeff(classes.friction(own, partner));
            dynamics->setSecondaryFrictionCoeff(classes.friction(own, partner));
            dynamics->setRestitutionCoeff(classes.restitution(own, partner));
            filter_->tag(sn, NodeTag{index, own, partner, body.isDynamic()});
            rec.shapes.push_back(sn);
        }
    }
}

void DartBackend::stepFrame(double dt) {
    if (!(dt > 0.0) || !std::isfinite(dt))
        throw InputError("dart: frame dt must be a positive finite number [s], got " + std::to_string(dt));
    long n = config_.stepsFor(dt);
    if (n > config_.max_substeps) {
        n = config_.max_substeps;
        ++step_cap_;
    }
    const double h = dt / static_cast<double>(n);
    world_->setTimeStep(h);
    for (long s = 0; s < n; ++s) internalStep(h, time_ + static_cast<double>(s + 1) * h);
    time_ += dt;
    ++frames_;
}

void DartBackend::internalStep(double h, double end_time) {
    if (config_.friction_axes == FrictionAxes::Sliding) alignFriction();
    const bool growing = config_.max_contacts == 0;
    if (growing) saveStates();
    for (;;) {
        world_->step();
        if (contactsFitted() || !growing) break;
        restoreSavedStates();  // taken again with the larger buffer: no contact dropped for room
    }
    ++internal_steps_;
    restoreNonfinite();
    readContacts(h, end_time);
    for (BodyRecord& rec : bodies_)
        if (rec.role == BodyRole::Tracked) placeTracked(rec, end_time);
}

bool DartBackend::contactsFitted() {
    if (world_->getLastCollisionResult().getNumContacts() < contact_capacity_) return true;
    if (config_.max_contacts > 0) {
        ++contact_cap_;
        return false;
    }
    contact_capacity_ *= 2;
    world_->getConstraintSolver()->getCollisionOption().maxNumContacts = contact_capacity_;
    ++buffer_growths_;
    return false;
}

void DartBackend::saveStates() {
    saved_.resize(bodies_.size());
    for (std::size_t i = 0; i < bodies_.size(); ++i)
        if (bodies_[i].role != BodyRole::Real) saved_[i] = frameState(bodies_[i]);
}

void DartBackend::restoreSavedStates() {
    for (std::size_t i = 0; i < bodies_.size(); ++i)
        if (bodies_[i].role != BodyRole::Real) setFrameState(bodies_[i], saved_[i]);
    world_->setTime(world_->getTime() - world_->getTimeStep());
}

void DartBackend::alignFriction() {
    for (BodyRecord& rec : bodies_) {
        if (rec.role != BodyRole::Virtual) continue;
        const Vec3 v = rec.node->getLinearVelocity();
        const Vec3 dir = v.norm() > 1e-9 ? Vec3(v.normalized()) : Vec3::Zero();  // zero: DART's own axes
        for (dd::ShapeNode* sn : rec.shapes) {
            dd::DynamicsAspect* dynamics = sn->getDynamicsAspect();
            dynamics->setFirstFrictionDirectionFrame(dd::Frame::World());
            dynamics->setFirstFrictionDirection(dir);
        }
    }
}

// The step's contacts: DART's normal points into collisionObject1's body (the solver pushes that
// body along +normal); Contact::force is the solved impulse over the step, normal part n lambda / h.
void DartBackend::readContacts(double h, double end_time) {
    const ::dart::collision::CollisionResult& result = world_->getLastCollisionResult();
    std::vector<SolvedContact> solved;
    std::set<std::pair<int, int>> touching;  // every pair the step found, with or without impulse
    solved.reserve(result.getNumContacts());
    for (const ::dart::collision::Contact& c : result.getContacts()) {
        const NodeTag* ta = filter_->find(c.collisionObject1->getShapeFrame());
        const NodeTag* tb = filter_->find(c.collisionObject2->getShapeFrame());
        if (!ta || !tb || !c.normal.allFinite() || !c.point.allFinite()) continue;
        SolvedContact s;
        const Vec3 n = c.normal.normalized();
        const bool a_first = ta->body < tb->body;
        s.body_a = a_first ? ta->body : tb->body;
        s.body_b = a_first ? tb->body : ta->body;
        s.point = c.point;
        s.normal_a_to_b = a_first ? Vec3(-n) : n;
        const double impulse = c.force.dot(n) * h;
        s.impulse = std::isfinite(impulse) && impulse > 0.0 ? impulse : 0.0;
        solved.push_back(s);
        touching.insert({s.body_a, s.body_b});
    }
    contact_points_ = solved.size();
    contact_points_total_ += contact_points_;
    events_.afterStep(solved, touching, end_time);
}

// The kinematic body at its motion's pose and velocities. A pose that overflows (a finite but
// huge velocity) is numerical trouble: counted, and the body stays where it was, at rest.
void DartBackend::placeTracked(BodyRecord& rec, double time) {
    Pose pose = rec.motion.poseAt(time);
    if (!bounded(pose.position) || !pose.orientation.coeffs().allFinite() ||
        !bounded(rec.motion.sample.linear_velocity) || !bounded(rec.motion.sample.angular_velocity)) {
        ++nonfinite_;
        rec.motion.t0 = time;
        rec.motion.sample.pose = Pose{rec.last_good.position, rec.last_good.orientation};
        rec.motion.sample.linear_velocity.setZero();
        rec.motion.sample.angular_velocity.setZero();
        pose = rec.motion.sample.pose;
    }
    FrameState s{pose.position, pose.orientation, rec.motion.sample.linear_velocity,
                 rec.motion.sample.angular_velocity};
    setFrameState(rec, s);
    rec.joint->setCommands(rec.joint->getVelocities());  // the VELOCITY actuator holds it
    rec.last_good = s;
}

void DartBackend::restoreNonfinite() {
    for (BodyRecord& rec : bodies_) {
        if (rec.role != BodyRole::Virtual) continue;  // tracked: placeTracked
        const FrameState s = frameState(rec);
        if (steppable(s.position, s.orientation, s.linear_velocity, s.angular_velocity)) {
            rec.last_good = s;
        } else {
            ++nonfinite_;
            setFrameState(rec, rec.last_good);
        }
    }
}

DartBackend::FrameState DartBackend::frameState(const BodyRecord& rec) const {
    FrameState s;
    const Eigen::Isometry3d& t = rec.node->getWorldTransform();
    s.position = t.translation();
    s.orientation = Quat(t.linear());
    s.linear_velocity = rec.node->getLinearVelocity();
    s.angular_velocity = rec.node->getAngularVelocity();
    return s;
}

// The FreeJoint's velocity is the body's spatial velocity in its own frame: [R^T w; R^T v].
void DartBackend::setFrameState(BodyRecord& rec, const FrameState& s) {
    const Pose pose{s.position, s.orientation.normalized()};
    rec.joint->setPositions(dd::FreeJoint::convertToPositions(isometry(pose)));
    const Mat3 rt = pose.orientation.toRotationMatrix().transpose();
    Eigen::Vector6d v;
    v.head<3>() = rt * s.angular_velocity;
    v.tail<3>() = rt * s.linear_velocity;
    rec.joint->setVelocities(v);
}

DartBackend::BodyRecord& DartBackend::record(int body, const char* what) {
    if (body < 0 || body >= bodyCount())
        throw InputError(std::string("dart: ") + what + ": no body with index " + std::to_string(body) + " (" +
                         std::to_string(bodyCount()) + " bodies)");
    return bodies_[static_cast<std::size_t>(body)];
}

BodyState DartBackend::bodyState(int body) const {
    if (body < 0 || body >= bodyCount())
        throw InputError("dart: bodyState: no body with index " + std::to_string(body) + " (" +
                         std::to_string(bodyCount()) + " bodies)");
    const BodyRecord& rec = bodies_[static_cast<std::size_t>(body)];
    BodyState out;
    if (rec.role == BodyRole::Real) {
        out.pose = rec.static_pose;
        return out;
    }
    const FrameState s = frameState(rec);
    out.pose.orientation = s.orientation;
    out.pose.position = s.position - s.orientation * rec.com;  // the scene's body frame origin
    out.linear_velocity = s.linear_velocity;                   // of the COM (the DART frame origin)
    out.angular_velocity = s.angular_velocity;
    return out;
}

void DartBackend::setBodyState(int body, const BodyState& state) {
    BodyRecord& rec = record(body, "setBodyState");
    if (rec.role == BodyRole::Real) return;  // real bodies do not move
    const Quat& q = state.pose.orientation;
    if (!bounded(state.pose.position) || !q.coeffs().allFinite() || !bounded(state.linear_velocity) ||
        !bounded(state.angular_velocity)) {
        ++nonfinite_;  // a tracker glitch (or a state DART cannot step): counted and refused, the body unchanged
        return;
    }
    if (q.norm() == 0.0)
        throw InputError("dart: setBodyState: body " + std::to_string(body) + ": expected a non-zero quaternion");
    if (rec.role == BodyRole::Tracked) {  // a tracker sample: this pose now, these velocities from now on
        rec.motion.t0 = time_;
        rec.motion.sample =
            BodyState{Pose{state.pose.position, q.normalized()}, state.linear_velocity, state.angular_velocity};
        placeTracked(rec, time_);
        return;
    }
    FrameState s;
    s.orientation = q.normalized();
    s.position = state.pose.position + s.orientation * rec.com;
    s.linear_velocity = state.linear_velocity;
    s.angular_velocity = state.angular_velocity;
    setFrameState(rec, s);
    rec.last_good = frameState(rec);
}

void DartBackend::applyImpulse(int body, const Vec3& impulse, const Vec3& world_point) {
    BodyRecord& rec = record(body, "applyImpulse");
    if (rec.role != BodyRole::Virtual) return;  // real and tracked bodies have infinite mass
    if (!impulse.allFinite() || !world_point.allFinite()) {
        ++nonfinite_;  // counted and ignored
        return;
    }
    const FrameState before = frameState(rec);
    // Directly as a velocity change: dv = J / m, dw = I_world^-1 ((p - com) x J).
    FrameState s = frameState(rec);
    const Mat3 r = s.orientation.toRotationMatrix();
    const Mat3 inertia_world = r * rec.inertia * r.transpose();
    s.linear_velocity += impulse / rec.mass;
    s.angular_velocity += inertia_world.ldlt().solve((world_point - s.position).cross(impulse));
    if (!steppable(s.position, s.orientation, s.linear_velocity, s.angular_velocity)) {
        ++nonfinite_;  // an impulse that would overflow the body: counted, the body unchanged
        setFrameState(rec, before);
        return;
    }
    setFrameState(rec, s);
}

WarningCounts DartBackend::warnings() const {
    return {{"nonfinite_state", nonfinite_},
            {"ill_conditioned_solve", lcp_ ? lcp_->dantzigFailures() : 0},  // Dantzig gave up; DART's PGS took over
            {"internal_step_cap", step_cap_},
            {"contacts_dropped", contact_cap_}};  // a fixed dart.max_contacts was filled: DART dropped the rest
}

Statistics DartBackend::statistics() const {
    const double steps = static_cast<double>(internal_steps_);
    auto mean = [&](std::uint64_t total) { return steps > 0 ? static_cast<double>(total) / steps : 0.0; };
    return {
        {"frames", static_cast<double>(frames_)},
        {"internal_steps", steps},
        {"collision_events", static_cast<double>(events_.eventTotal())},
        {"contact_points", static_cast<double>(contact_points_)},
        {"contact_points_mean", mean(contact_points_total_)},
        {"dart.pairs_in_contact", static_cast<double>(events_.pairsInContact())},
        {"dart.mesh_collision_for_hulls", mesh_for_hulls_ ? 1.0 : 0.0},
        {"dart.contact_buffer", static_cast<double>(contact_capacity_)},
        {"dart.contact_buffer_growths", static_cast<double>(buffer_growths_)},
        {"dart.pgs_solves", lcp_ ? static_cast<double>(lcp_->pgsSolves()) : 0.0},
    };
}

}  // namespace vroc::dart
