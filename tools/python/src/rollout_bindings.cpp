// SPDX-License-Identifier: MIT
// vroc.rollout: a batch of initial states on several backends, on the run pool, the GIL released.
#include <cstring>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "py_convert.h"
#include "rollout.h"
#include "state_rows.h"
#include "vroc/core/errors.h"

namespace vroc::python {

void bindRollout(py::module_& m) {
    m.def(
        "_rollout",
        [](std::shared_ptr<Scene> scene, const std::vector<std::string>& backends, const py::handle& initial_states,
           std::int64_t frames, int jobs, const py::handle& settings, std::optional<double> dt) {
            const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(initial_states);
            const auto n = static_cast<py::ssize_t>(scene->bodies.size());
            if (!a || a.ndim() != 3 || a.shape(1) != n || a.shape(2) != kStateWidth)
                throw InputError("rollout: initial_states must have shape (B, " + std::to_string(n) + ", " +
                                 std::to_string(kStateWidth) + ") (members, scene bodies, state)");
            if (backends.empty()) throw InputError("rollout: backends is empty");
            if (dt && !(*dt > 0)) throw InputError("rollout: dt must be a positive number of seconds");
            RolloutRequest r;
            r.scene = scene.get();
            for (const std::string& b : backends) r.backends += (r.backends.empty() ? "" : ",") + b;
            for (const auto& [key, value] : settingPairs(settings)) r.assignments.push_back(key + "=" + value);
            const std::size_t per = static_cast<std::size_t>(n) * kStateWidth;
            for (py::ssize_t b = 0; b < a.shape(0); ++b)
                r.initial.push_back(readStateRows({a.data() + b * per, per}, *scene));
            r.frames = frames;
            r.frame_dt = dt ? *dt : 0.0;
            r.jobs = jobs;
            RolloutResult result;
            {
                py::gil_scoped_release release;
                result = runRollout(r);
            }
            const auto nb = static_cast<py::ssize_t>(result.backends.size());
            py::array_t<double> states({nb, a.shape(0), static_cast<py::ssize_t>(frames), n, static_cast<py::ssize_t>(kStateWidth)});
            std::memcpy(states.mutable_data(), result.states.data(), result.states.size() * sizeof(double));
            py::list events, warnings, hashes;
            for (const auto& per_backend : result.members) {
                py::list e, w, h;
                for (const RolloutMember& member : per_backend) {
                    e.append(eventArray(member.events));
                    w.append(py::cast(member.warnings));
                    h.append(member.state_hash);
                }
                events.append(e);
                warnings.append(w);
                hashes.append(h);
            }
            py::dict out;
            out["backends"] = result.backends;
            out["states"] = states;
            out["events"] = events;
            out["warnings"] = warnings;
            out["state_hashes"] = hashes;
            out["wall_s"] = result.wall_s;
            return out;
        },
        py::arg("scene"), py::arg("backends"), py::arg("initial_states"), py::arg("frames"), py::arg("jobs") = 1,
        py::arg("settings") = py::none(), py::arg("dt") = py::none());
}

}  // namespace vroc::python
