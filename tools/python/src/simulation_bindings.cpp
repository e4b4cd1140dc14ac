// SPDX-License-Identifier: MIT
// vroc.Simulation: one backend stepping one scene, with the GIL released while it steps, and every
// body's state as NumPy arrays in one call.
//
// Arrays: positions, orientations, linear_velocities and angular_velocities are read-only, C-ordered
// arrays of one snapshot, taken the first time one of them is read after the state changed; a later
// step makes a new snapshot, so an array once handed out never changes. state() is a writable copy
// (N, 13); set_state() is the one way to write.
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "py_convert.h"
#include "simulation.h"
#include "state_rows.h"
#include "vroc/core/errors.h"
#include "vroc/core/scene_loader.h"

namespace vroc::python {
namespace {

/// The read-only arrays of one snapshot of every body's state.
struct StateViews {
    py::array_t<double> positions, orientations, linear_velocities, angular_velocities;
};

py::array_t<double> readOnly(py::array_t<double> a) {
    py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    return a;
}

class PySimulation {
public:
    PySimulation(std::shared_ptr<const Scene> scene, const std::string& backend, const py::handle& settings,
                 std::optional<double> dt)
        : sim_(std::move(scene), backend, settingPairs(settings), dt ? *dt : 0.0) {
        if (dt && !(*dt > 0)) throw InputError("dt: expected a positive number of seconds");
    }

    void step(std::int64_t frames) {
        {
            py::gil_scoped_release release;
            std::lock_guard lock(mutex_);
            sim_.step(frames);
        }
        views_.reset();
    }
    std::int64_t run(double seconds) {
        std::int64_t n = 0;
        {
            py::gil_scoped_release release;
            std::lock_guard lock(mutex_);
            n = sim_.run(seconds);
        }
        views_.reset();
        return n;
    }

    const StateViews& views() {
        if (views_) return *views_;
        std::lock_guard lock(mutex_);
        const auto n = static_cast<py::ssize_t>(sim_.bodyCount());
        StateViews s{py::array_t<double>({n, py::ssize_t{3}}), py::array_t<double>({n, py::ssize_t{4}}),
                   py::array_t<double>({n, py::ssize_t{3}}), py::array_t<double>({n, py::ssize_t{3}})};
        double* p = s.positions.mutable_data();
        double* q = s.orientations.mutable_data();
        double* v = s.linear_velocities.mutable_data();
        double* w = s.angular_velocities.mutable_data();
        double row[kStateWidth];
        for (py::ssize_t i = 0; i < n; ++i) {
            writeStateRow(sim_.bodyState(static_cast<int>(i)), row);
            for (int k = 0; k < 3; ++k) p[3 * i + k] = row[kPositionColumn + k];
            for (int k = 0; k < 4; ++k) q[4 * i + k] = row[kOrientationColumn + k];
            for (int k = 0; k < 3; ++k) v[3 * i + k] = row[kLinearVelocityColumn + k];
            for (int k = 0; k < 3; ++k) w[3 * i + k] = row[kAngularVelocityColumn + k];
        }
        views_ = StateViews{readOnly(s.positions), readOnly(s.orientations), readOnly(s.linear_velocities),
                             readOnly(s.angular_velocities)};
        return *views_;
    }

    py::array_t<double> state() {
        std::lock_guard lock(mutex_);
        const auto n = static_cast<py::ssize_t>(sim_.bodyCount());
        py::array_t<double> a({n, static_cast<py::ssize_t>(kStateWidth)});
        for (py::ssize_t i = 0; i < n; ++i) writeStateRow(sim_.bodyState(static_cast<int>(i)), a.mutable_data() + i * kStateWidth);
        return a;
    }

    void setState(const py::handle& value) {
        const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
        const auto n = static_cast<py::ssize_t>(sim_.scene().bodies.size());
        if (!a || a.ndim() != 2 || a.shape(0) != n || a.shape(1) != kStateWidth)
            throw InputError("set_state: expected an array of shape (" + std::to_string(n) + ", " +
                             std::to_string(kStateWidth) + ") (one row per scene body: position, orientation x y z w, "
                             "linear and angular velocity)");
        const std::vector<BodyState> states = readStateRows({a.data(), static_cast<std::size_t>(a.size())}, sim_.scene());
        {
            std::lock_guard lock(mutex_);
            sim_.setStates(states);
        }
        views_.reset();
    }

    void applyImpulse(int body, const py::handle& impulse, const py::handle& point) {
        const Vec3 j = vec3From(impulse, "apply_impulse: impulse");
        const Vec3 x = vec3From(point, "apply_impulse: point");
        {
            std::lock_guard lock(mutex_);
            sim_.applyImpulse(body, j, x);
        }
        views_.reset();
    }

    void restore(const Simulation::Snapshot& snapshot) {
        {
            py::gil_scoped_release release;
            std::lock_guard lock(mutex_);
            sim_.restore(snapshot);
        }
        views_.reset();
    }

    Simulation& sim() { return sim_; }
    std::mutex& mutex() { return mutex_; }

private:
    Simulation sim_;
    std::mutex mutex_;   // a second Python thread must not read while this simulation steps without the GIL
    std::optional<StateViews> views_;
};

/// A binding that calls f(simulation) under the simulation's lock (another Python thread may be
/// stepping it without the GIL).
template <class F>
auto locked(F f) {
    return [f](PySimulation& s) {
        std::lock_guard lock(s.mutex());
        return f(s.sim());
    };
}

std::shared_ptr<const Scene> sceneFrom(const py::handle& scene) {
    if (py::isinstance<Scene>(scene)) return scene.cast<std::shared_ptr<Scene>>();
    const py::object os = py::module_::import("os");
    try {
        return std::make_shared<Scene>(loadScene(os.attr("fspath")(scene).cast<std::string>()));
    } catch (const py::error_already_set&) {
        throw InputError("scene: expected a vroc.Scene or a path to a scene file");
    }
}

}  // namespace

void bindSimulation(py::module_& m) {
    py::class_<Simulation::Snapshot>(m, "Snapshot",
                                     "What Simulation.restore needs to bring a simulation back exactly: the inputs "
                                     "since creation (set_state, apply_impulse) at their frames, and the frame count.")
        .def_property_readonly("frames", [](const Simulation::Snapshot& s) { return s.frames; })
        .def_property_readonly("inputs", [](const Simulation::Snapshot& s) { return s.inputs.size(); });
    py::class_<PySimulation>(m, "Simulation",
                             "One backend stepping one scene: Simulation(scene, backend='native', settings=None, dt=None).\n"
                             "scene: a vroc.Scene or a path; settings: {key: value}, a key with or without the backend "
                             "prefix ('substeps' or 'bullet.substeps'); dt: frame step [s], default the scene's.")
        .def(py::init([](const py::handle& scene, const std::string& backend, const py::handle& settings,
                         std::optional<double> dt) {
                 return std::make_unique<PySimulation>(sceneFrom(scene), backend, settings, dt);
             }),
             py::arg("scene"), py::arg("backend") = "native", py::arg("settings") = py::none(), py::arg("dt") = py::none())
        .def("step", &PySimulation::step, py::arg("frames") = 1, "Steps `frames` frames (the GIL is released).")
        .def("run", &PySimulation::run, py::arg("seconds"),
             "Steps the frames that cover `seconds` (as `vroc run --duration`); returns how many.")
        .def_property_readonly("time", [](PySimulation& s) { return s.sim().time(); }, "[s] simulation time")
        .def_property_readonly("frames", [](PySimulation& s) { return s.sim().frames(); }, "frames stepped")
        .def_property_readonly("dt", [](PySimulation& s) { return s.sim().frameDt(); }, "[s] frame step")
        .def_property_readonly("backend", [](PySimulation& s) { return s.sim().info().name; })
        .def_property_readonly("settings", [](PySimulation& s) { return settingsDict(s.sim().info(), s.sim().settings()); },
                               "every setting of the backend, resolved {key: value}")
        .def_property_readonly("scene", [](PySimulation& s) { return std::make_shared<Scene>(s.sim().scene()); },
                               "a copy of the scene")
        .def_property_readonly("body_count", [](PySimulation& s) { return s.sim().bodyCount(); })
        .def_property_readonly("positions", [](PySimulation& s) { return s.views().positions; },
                               "(N, 3) [m] body frame origins; read-only snapshot")
        .def_property_readonly("orientations", [](PySimulation& s) { return s.views().orientations; },
                               "(N, 4) unit quaternions x y z w; read-only snapshot")
        .def_property_readonly("linear_velocities", [](PySimulation& s) { return s.views().linear_velocities; },
                               "(N, 3) [m/s] of the centres of mass; read-only snapshot")
        .def_property_readonly("angular_velocities", [](PySimulation& s) { return s.views().angular_velocities; },
                               "(N, 3) [rad/s]; read-only snapshot")
        .def("state", &PySimulation::state,
             "(N, 13) writable copy: position, orientation x y z w, linear velocity, angular velocity")
        .def("set_state", &PySimulation::setState, py::arg("state"),
             "Sets every body from an (N, 13) array (set_state(state()) changes no bit). A real body's row must "
             "equal its current state; a tracked body takes its row as a tracker sample.")
        .def("apply_impulse", &PySimulation::applyImpulse, py::arg("body"), py::arg("impulse"), py::arg("point"),
             "Applies an impulse [N s] at a world point [m] to a virtual body.")
        .def("snapshot", locked([](Simulation& s) { return s.snapshot(); }), "A Snapshot of this simulation, for restore().")
        .def("restore", &PySimulation::restore, py::arg("snapshot"),
             "Brings the simulation back to a snapshot of it, the same bits on every backend: a fresh backend "
             "replays the snapshot's inputs and frames (so it costs those frames again). Events and step times "
             "start afresh.")
        .def("events", locked([](Simulation& s) { return eventArray(s.takeEvents()); }), "Collision events since the previous call: a structured array of dtype vroc.EVENT_DTYPE.")
        .def("statistics", locked([](Simulation& s) { return s.statistics(); }), "Backend statistics {name: value}")
        .def("warnings", locked([](Simulation& s) { return s.warnings(); }), "Counted numerical warnings {name: count}")
        .def_property_readonly("state_hash", locked([](Simulation& s) { return s.stateHash(); }), "FNV-1a over every body's state bits: equal to `vroc run`'s state_hash after the same frames")
        .def_property_readonly("step_times",
                               locked([](Simulation& s) {
                                   const auto& t = s.stepWallTimes();
                                   return py::array_t<double>(static_cast<py::ssize_t>(t.size()), t.data());
                               }),
                               "[s] wall time of every frame's stepFrame")
        .def_property_readonly("last_step_span", [](PySimulation& s) { return s.sim().lastStepSpan(); },
                               "(start, end) [s, steady clock] of the last step()/run() call's stepping")
        .def("__repr__", [](PySimulation& s) {
            return "<vroc.Simulation '" + s.sim().scene().name + "' on " + s.sim().info().name + " at t=" +
                   py::repr(py::float_(s.sim().time())).cast<std::string>() + ">";
        });
}

}  // namespace vroc::python
