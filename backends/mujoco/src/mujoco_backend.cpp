// SPDX-License-Identifier: MIT
#include "mujoco_backend.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "contact_materials.h"
#include "mjcf_writer.h"
#include "principal_frame.h"
#include "restitution_mapping.h"
#include "vroc/core/body_motion_checks.h"
#include "vroc/core/errors.h"

namespace vroc::mujoco {
namespace {

// Equal internal steps per frame: the fewest that are no longer than `timestep`. The tolerance
// keeps a dt that is a whole multiple of the timestep up to rounding (0.01 / 0.002) at 5, not 6.
long stepsFor(double dt, double timestep) {
    const double q = dt / timestep;
    return std::max(1L, static_cast<long>(std::ceil(q - 1e-9)));
}

// Internal steps for a frame of dt: mujoco.substeps if set, else from mujoco.timestep.
long stepsFor(double dt, const MujocoConfig& config) {
    return config.substeps > 0 ? config.substeps : stepsFor(dt, config.timestep);
}

// With fixed sub-steps the configuration is remade for the scene's frame: the restitution mapping
// for the step dt / substeps, the contact spring no faster than 2 steps (MuJoCo's rule).
MujocoConfig forFrame(const MujocoConfig& config, double frame_dt) {
    if (config.substeps <= 0) return config;
    MujocoConfig c = config;
    c.timestep = frame_dt / static_cast<double>(config.substeps);
    c.contact_timeconst = std::max(config.contact_timeconst, 2.0 * c.timestep);
    return c;
}

// Everything the MJCF and the body records rely on, checked before MuJoCo sees anything.
void validate(const Scene& scene, const MujocoConfig& config) {
    const std::string where = "mujoco: scene '" + scene.name + "': ";
    if (config.contact_timeconst < 2.0 * config.timestep)
        throw InputError(where + "mujoco.contact_timeconst (" + std::to_string(config.contact_timeconst) +
                         " s) must be at least 2 x mujoco.timestep (" + std::to_string(config.timestep) +
                         " s): MuJoCo's rule for a stable contact spring");
    for (const Body& body : scene.bodies) {
        if (body.material < 0 || static_cast<std::size_t>(body.material) >= scene.materials.size())
            throw InputError(where + "body '" + body.name + "': material index " + std::to_string(body.material) +
                             " out of range");
        auto checkShape = [&](const Shape& s) {
            if (s.kind == Shape::Kind::Hull && (!s.hull || s.hull->vertices.size() < 4))
                throw InputError(where + "body '" + body.name + "': a hull needs at least 4 vertices");
            if (s.kind == Shape::Kind::Compound)
                throw InputError(where + "body '" + body.name + "': nested compound (the scene loader flattens them)");
        };
        if (body.shape.kind == Shape::Kind::Compound) {
            if (body.shape.parts.empty()) throw InputError(where + "body '" + body.name + "': empty compound");
            for (const ShapePart& p : body.shape.parts) checkShape(p.shape);
        } else {
            checkShape(body.shape);
        }
        if (body.isStatic()) continue;
        if (body.isTracked()) {   // infinite mass: no mass properties; its motion must be finite
            if (!hasFiniteMotion(body))
                throw InputError(where + "body '" + body.name +
                                 "': a tracked body needs a finite pose (non-zero quaternion) and finite velocities");
            continue;
        }
        const PrincipalFrame pf = principalFrame(body.mass_properties);
        if (!(body.mass_properties.mass > 0.0) || !std::isfinite(body.mass_properties.mass) ||
            !(pf.principal_inertia.minCoeff() > 0.0) || !pf.principal_inertia.allFinite())
            throw InputError(where + "body '" + body.name +
                             "': a virtual body needs positive mass and positive principal inertia");
    }
}

// The settings' words in MJCF's: the integrator keywords are MuJoCo 2.2's ("Euler", "RK4",
// "implicit": the integrator map of its XML reader), the cone keywords are the settings' own.
// The settings machinery admits only these words; a MujocoConfig built by hand is checked too.
SolverOptions solverOptions(const MujocoConfig& config, double timestep) {
    SolverOptions o;
    o.timestep = timestep;
    if (config.cone != "pyramidal" && config.cone != "elliptic")
        throw InputError("mujoco: mujoco.cone: expected pyramidal or elliptic, got '" + config.cone + "'");
    o.cone = config.cone;
    // Elliptic cone with the restitution mapping: the friction rows get the damping of a perfectly
    // inelastic pair whatever the pair's e (friction_damping.h says why).
    if (config.cone == "elliptic" && config.restitution == "solref")
        o.friction_damping = contactSpring(0.0, config.contact_timeconst, config.timestep).damping;
    o.impratio = config.impratio;
    o.noslip_iterations = config.noslip_iterations;
    o.box_depth_bound = config.bound_box_depth;
    if (config.integrator == "euler")
        o.integrator = "Euler";
    else if (config.integrator == "rk4")
        o.integrator = "RK4";
    else if (config.integrator == "implicit")
        o.integrator = "implicit";
    else
        throw InputError("mujoco: mujoco.integrator: expected euler, rk4 or implicit, got '" + config.integrator + "'");
    return o;
}

ModelPtr compile(const Scene& scene, const MujocoConfig& given) {
    const MujocoConfig config = forFrame(given, scene.frame_dt);
    validate(scene, config);
    const ContactMaterials materials(scene, config.contact_timeconst, config.timestep, config.restitution == "solref");
    const double h = scene.frame_dt / static_cast<double>(stepsFor(scene.frame_dt, config.timestep));
    return loadModel(writeMjcf(scene, materials, solverOptions(config, h)), scene.name);
}

DataPtr makeData(const mjModel& m) {
    mjData* d = nullptr;
    try {
        d = mj_makeData(&m);
    } catch (const RunError& e) {   // from the error handler (model_loader.h)
        throw InputError(std::string("mujoco: cannot allocate mjData: ") + e.what());
    }
    if (!d) throw InputError("mujoco: cannot allocate mjData");
    return DataPtr(d);
}

int bodyId(const mjModel& m, int scene_body) {
    const int id = mj_name2id(&m, mjOBJ_BODY, bodyName(scene_body).c_str());
    if (id < 0) throw InputError("mujoco: compiled model lacks body " + bodyName(scene_body));
    return id;
}

// Scene body index of every MuJoCo geom (-1 for geoms of no scene body; there are none).
std::vector<int> geomBodies(const mjModel& m, const Scene& scene) {
    std::vector<int> of_mj_body(static_cast<std::size_t>(m.nbody), -1);
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
        of_mj_body[static_cast<std::size_t>(bodyId(m, static_cast<int>(i)))] = static_cast<int>(i);
    std::vector<int> out(static_cast<std::size_t>(m.ngeom));
    for (int g = 0; g < m.ngeom; ++g) out[static_cast<std::size_t>(g)] = of_mj_body[static_cast<std::size_t>(m.geom_bodyid[g])];
    return out;
}

Mat3 rotation(const double* q) { return Quat(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix(); }

bool finiteState(const BodyState& s) {
    return s.pose.position.allFinite() && s.pose.orientation.coeffs().allFinite() && s.linear_velocity.allFinite() &&
           s.angular_velocity.allFinite();
}

}  // namespace

MujocoBackend::MujocoBackend(const Scene& scene, const MujocoConfig& config)
    : config_(config),
      model_(compile(scene, config)),
      data_(makeData(*model_)),
      events_(scene.collision_distance, geomBodies(*model_, scene)),
      guard_(*model_, *data_, {}) {
    const mjModel& m = *model_;
    std::vector<BodySlots> slots;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        const Body& body = scene.bodies[i];
        BodyRecord rec;
        rec.role = body.role;
        rec.pose = body.pose;
        if (body.isTracked()) {
            const TrackedInertia t = trackedInertia(scene, body);
            rec.mass = t.mass;
            rec.principal_inertia = Vec3::Constant(t.inertia);
            rec.motion.sample = BodyState{Pose{body.pose.position, body.pose.orientation.normalized()},
                                          body.linear_velocity, body.angular_velocity};
        } else if (body.isDynamic()) {
            const PrincipalFrame pf = principalFrame(body.mass_properties);
            rec.com_in_body = pf.com_in_body;
            rec.mass = body.mass_properties.mass;
            rec.principal_inertia = pf.principal_inertia;
        }
        if (!body.isStatic()) {
            const int id = bodyId(m, static_cast<int>(i));
            const int joint = m.body_jntadr[id];
            rec.slots = {m.jnt_qposadr[joint], m.jnt_dofadr[joint]};
            // qpos0 is the placed pose from the MJCF; the velocities are the scene's.
            double* qvel = data_->qvel + rec.slots.dof;
            const Mat3 R = rotation(data_->qpos + rec.slots.qpos + 3);
            const Vec3 w_local = R.transpose() * body.angular_velocity;
            for (int k = 0; k < 3; ++k) {
                qvel[k] = body.linear_velocity[k];
                qvel[3 + k] = w_local[k];
            }
        }
        slots.push_back(rec.slots);
        bodies_.push_back(rec);
        if (body.isTracked()) placeTracked(bodies_.back(), 0.0);
    }
    try {
        mj_forward(model_.get(), data_.get());   // derived quantities for the initial state
    } catch (const RunError& e) {
        throw InputError(std::string("mujoco: scene '") + scene.name + "': MuJoCo failed on the initial state: " + e.what());
    }
    guard_ = StateGuard(*model_, *data_, std::move(slots));
}

void MujocoBackend::stepFrame(double dt) {
    if (!(dt > 0.0) || !std::isfinite(dt))
        throw InputError("mujoco: frame dt must be a positive finite number, got " + std::to_string(dt));
    long n = stepsFor(dt, config_);
    if (n > config_.max_substeps) {
        n = config_.max_substeps;
        ++step_cap_;
    }
    const double h = dt / static_cast<double>(n);
    model_->opt.timestep = h;
    for (long s = 0; s < n; ++s) internalStep(h, time_ + static_cast<double>(s + 1) * h);
    time_ += dt;
    ++frames_;
}

// One internal step; tracked bodies then go to where their motion has them at its end, which is
// where the next step starts: every step collides the bodies at one time.
void MujocoBackend::internalStep(double h, double end_time) {
    mujocoStep(h, end_time);
    for (BodyRecord& rec : bodies_)
        if (rec.role == BodyRole::Tracked) placeTracked(rec, end_time);
}

// One mj_step, checked. A step that overflowed MuJoCo's buffers (the contact list, the constraint
// rows, the scratch stack) is taken again from its start with larger ones (growBuffers), so no
// contact is dropped for want of room. A bad step is undone (state_guard.h); if that put a body
// back, the step is taken once more from the repaired state, and if it fails again the blamed
// bodies stay at their last good pose, at rest, for this step.
void MujocoBackend::mujocoStep(double h, double end_time) {
    for (int attempt = 0; attempt < 2; ++attempt) {
        guard_.beforeStep(*data_);
        bool threw = false;
        for (int growth = 0;; ++growth) {
            holdTrackedWeight();   // (a reset after an error clears qfrc_applied)
            data_->time = end_time - h;
            threw = false;
            std::string error;
            try {
                mj_step(model_.get(), data_.get());
            } catch (const RunError& e) {   // from the error handler (model_loader.h)
                threw = true;
                error = e.what();
            }
            const bool contacts_full = data_->warning[mjWARN_CONTACTFULL].number > 0;
            const bool rows_full = data_->warning[mjWARN_CNSTRFULL].number > 0;
            const bool stack_full = threw && error.find("tack overflow") != std::string::npos;
            if (!(contacts_full || rows_full || stack_full) || growth >= kMaxGrowthsPerStep ||
                !growBuffers(contacts_full, rows_full, stack_full))
                break;
            guard_.restoreStart(*data_);   // the new mjData starts where the step started
        }
        ++internal_steps_;
        if (guard_.afterStep(*model_, *data_, threw)) {
            events_.afterStep(*model_, *data_, h, end_time);
            last_ncon_ = data_->ncon;
            last_nefc_ = data_->nefc;
            solver_iterations_ += static_cast<std::uint64_t>(data_->solver_iter);
            if (model_->nuserdata > 0) {   // the passive callback's corrections in this step
                phantom_contacts_ += static_cast<std::uint64_t>(data_->userdata[0]);
                data_->userdata[0] = 0;
            }
            return;
        }
        const int put_back = guard_.recover(*model_, *data_, attempt > 0);
        nonfinite_ += static_cast<std::uint64_t>(put_back);
        events_.reset();
        if (put_back == 0) return;   // nothing changed: a retry would repeat the trouble
    }
}

// Doubles what overflowed and allocates a new mjData (MuJoCo 2.2 sizes it from the model once).
// The constraint rows are dear in 2.2 (njmax x njmax and njmax x nv arrays, 12 r^2 + 24 r nv
// bytes for r rows): they grow only while
// those arrays stay within kMaxRowBytes (the last growth stops at that size); past that a full row
// list stays counted as mujoco.constraint_full (rows dropped). Returns false when nothing could grow.
bool MujocoBackend::growBuffers(bool contacts, bool rows, bool stack) {
    mjModel& m = *model_;
    const int old_nconmax = m.nconmax, old_njmax = m.njmax, old_nstack = m.nstack;
    bool grown = false;
    if (contacts && m.nconmax < (1 << 24)) {
        m.nconmax *= 2;
        grown = true;
    }
    if (rows) {  // doubled, or as many rows as kMaxRowBytes allows when doubling would pass it
        const double b = 24.0 * m.nv;
        const double at_cap = std::floor((-b + std::sqrt(b * b + 48.0 * kMaxRowBytes)) / 24.0);
        const int target = static_cast<int>(std::min(2.0 * m.njmax, at_cap));
        if (target > m.njmax + m.njmax / 16) {
            m.njmax = target;
            grown = true;
        }
    }
    // The scratch stack holds arrays linear in the rows and dofs (mjcf_writer.cpp's first guess).
    const long needed = 1000000L + 2000L * (static_cast<long>(m.nv) + m.njmax);
    if ((stack || needed > m.nstack) && m.nstack < (1 << 28)) {
        m.nstack = static_cast<int>(std::max(needed, stack ? 2L * m.nstack : needed));
        grown = true;
    }
    if (!grown) return false;
    try {
        data_ = makeData(m);
    } catch (const InputError&) {   // MuJoCo could not allocate it: keep the old buffers
        m.nconmax = old_nconmax;
        m.njmax = old_njmax;
        m.nstack = old_nstack;
        return false;
    }
    ++buffer_growths_;
    return true;
}

// A tracked body's weight, cancelled on its free joint's translational dofs (MuJoCo 2.2 has no
// gravity compensation of its own): during a step it moves at its velocity, and the contact
// solve, which couples its acceleration with the virtual body's, sees no gravity on it.
void MujocoBackend::holdTrackedWeight() {
    const double* g = model_->opt.gravity;
    for (const BodyRecord& rec : bodies_) {
        if (rec.role != BodyRole::Tracked) continue;
        double* f = data_->qfrc_applied + rec.slots.dof;
        for (int k = 0; k < 3; ++k) {
            f[k] = -rec.mass * g[k];
            f[3 + k] = 0.0;
        }
    }
}

// qpos and qvel of the tracker motion at `time`. A pose beyond MuJoCo's range (a finite but huge
// velocity) is numerical trouble: counted, and the body stays where it was, at rest, from then on.
void MujocoBackend::placeTracked(BodyRecord& rec, double time) {
    Pose pose = rec.motion.poseAt(time);
    const auto inRange = [](const Vec3& p) { return p.cwiseAbs().maxCoeff() <= mjMAXVAL; };   // false for NaN
    if (!inRange(pose.position) || !pose.orientation.coeffs().allFinite()) {
        ++nonfinite_;
        rec.motion.t0 = time;
        rec.motion.sample.pose = comPose(rec);
        rec.motion.sample.linear_velocity.setZero();
        rec.motion.sample.angular_velocity.setZero();
        pose = rec.motion.sample.pose;
    }
    double* q = data_->qpos + rec.slots.qpos;
    double* v = data_->qvel + rec.slots.dof;
    const Vec3 w_local = pose.orientation.conjugate() * rec.motion.sample.angular_velocity;
    for (int k = 0; k < 3; ++k) {
        q[k] = pose.position[k];
        v[k] = rec.motion.sample.linear_velocity[k];
        v[3 + k] = w_local[k];
    }
    q[3] = pose.orientation.w();
    q[4] = pose.orientation.x();
    q[5] = pose.orientation.y();
    q[6] = pose.orientation.z();
}

MujocoBackend::BodyRecord& MujocoBackend::record(int body, const char* what) {
    return const_cast<BodyRecord&>(static_cast<const MujocoBackend*>(this)->record(body, what));
}

const MujocoBackend::BodyRecord& MujocoBackend::record(int body, const char* what) const {
    if (body < 0 || body >= bodyCount())
        throw InputError(std::string("mujoco: ") + what + ": no body with index " + std::to_string(body));
    return bodies_[static_cast<std::size_t>(body)];
}

Pose MujocoBackend::comPose(const BodyRecord& rec) const {
    const double* q = data_->qpos + rec.slots.qpos;
    return {Vec3(q[0], q[1], q[2]), Quat(q[3], q[4], q[5], q[6]).normalized()};
}

BodyState MujocoBackend::bodyState(int body) const {
    const BodyRecord& rec = record(body, "bodyState");
    BodyState s;
    if (rec.role == BodyRole::Real) {
        s.pose = rec.pose;
        return s;
    }
    const Pose com = comPose(rec);
    s.pose = com * rec.com_in_body.inverse();   // the scene's body frame
    if (s.pose.orientation.w() < 0.0) s.pose.orientation.coeffs() *= -1.0;   // same rotation, w >= 0
    const double* v = data_->qvel + rec.slots.dof;
    s.linear_velocity = Vec3(v[0], v[1], v[2]);   // body frame origin = COM
    s.angular_velocity = com.orientation * Vec3(v[3], v[4], v[5]);   // local -> world
    if (rec.role == BodyRole::Tracked) s.angular_velocity = rec.motion.sample.angular_velocity;   // no round trip
    return s;
}

void MujocoBackend::setBodyState(int body, const BodyState& state) {
    BodyRecord& rec = record(body, "setBodyState");
    if (rec.role == BodyRole::Real) return;
    if (!finiteState(state)) {   // a tracker glitch: refused and counted, the body unchanged
        ++nonfinite_;
        return;
    }
    if (!(state.pose.orientation.norm() > 1e-9))   // finite but no rotation: the caller's mistake
        throw InputError("mujoco: setBodyState: body " + std::to_string(body) + ": expected a non-zero quaternion");
    if (rec.role == BodyRole::Tracked) {   // a tracker sample: this pose now, these velocities from now on
        rec.motion.t0 = time_;
        rec.motion.sample = BodyState{Pose{state.pose.position, state.pose.orientation.normalized()},
                                      state.linear_velocity, state.angular_velocity};
        placeTracked(rec, time_);
        return;
    }
    Pose com{state.pose.position, state.pose.orientation.normalized()};
    com = com * rec.com_in_body;
    double* q = data_->qpos + rec.slots.qpos;
    double* v = data_->qvel + rec.slots.dof;
    const Vec3 w_local = com.orientation.conjugate() * state.angular_velocity;
    for (int k = 0; k < 3; ++k) {
        q[k] = com.position[k];
        v[k] = state.linear_velocity[k];
        v[3 + k] = w_local[k];
    }
    q[3] = com.orientation.w();
    q[4] = com.orientation.x();
    q[5] = com.orientation.y();
    q[6] = com.orientation.z();
}

void MujocoBackend::applyImpulse(int body, const Vec3& impulse, const Vec3& world_point) {
    const BodyRecord& rec = record(body, "applyImpulse");
    if (rec.role != BodyRole::Virtual) return;   // real and tracked bodies have infinite mass
    if (!impulse.allFinite() || !world_point.allFinite()) {
        ++nonfinite_;
        return;
    }
    // Straight onto the velocities: dv = J / m at the COM, dw = I^-1 (r x J) with I diagonal in
    // the MuJoCo body frame, where the free joint keeps its angular velocity.
    const Pose com = comPose(rec);
    const Vec3 torque_local = com.orientation.conjugate() * (world_point - com.position).cross(impulse);
    double* v = data_->qvel + rec.slots.dof;
    for (int k = 0; k < 3; ++k) {
        v[k] += impulse[k] / rec.mass;
        v[3 + k] += torque_local[k] / rec.principal_inertia[k];
    }
}

WarningCounts MujocoBackend::warnings() const {
    WarningCounts w = guard_.counts();
    w["nonfinite_state"] = nonfinite_;
    w["internal_step_cap"] = step_cap_;
    return w;
}

Statistics MujocoBackend::statistics() const {
    const double steps = static_cast<double>(internal_steps_);
    return {
        {"frames", static_cast<double>(frames_)},
        {"internal_steps", steps},
        {"collision_events", static_cast<double>(events_.eventTotal())},
        {"contact_points", static_cast<double>(last_ncon_)},
        {"contact_points_mean", steps > 0 ? static_cast<double>(events_.contactPointTotal()) / steps : 0.0},
        {"mujoco.pairs_in_contact", static_cast<double>(events_.pairsInContact())},
        {"mujoco.explicit_pairs", static_cast<double>(model_->npair)},
        {"mujoco.constraint_rows", static_cast<double>(last_nefc_)},
        {"mujoco.solver_iterations_mean", steps > 0 ? static_cast<double>(solver_iterations_) / steps : 0.0},
        {"mujoco.buffer_growths", static_cast<double>(buffer_growths_)},
        {"mujoco.nconmax", static_cast<double>(model_->nconmax)},
        {"mujoco.njmax", static_cast<double>(model_->njmax)},
        {"mujoco.nstack", static_cast<double>(model_->nstack)},
        {"mujoco.phantom_contacts", static_cast<double>(phantom_contacts_)},
    };
}

}  // namespace vroc::mujoco
