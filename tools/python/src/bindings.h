// SPDX-License-Identifier: MIT
// The parts of the Python module `vroc._vroc` (docs/python.md), one file each; module.cpp calls them.
#pragma once

#include <pybind11/pybind11.h>

namespace vroc::python {

namespace py = pybind11;

void bindScene(py::module_& m);        ///< Scene, Body, Material, load_scene (scene_bindings.cpp)
void bindBackends(py::module_& m);     ///< backends(), BackendInfo, SettingSpec (backend_bindings.cpp)
void bindSimulation(py::module_& m);   ///< Simulation (simulation_bindings.cpp)
void bindRollout(py::module_& m);      ///< rollout (rollout_bindings.cpp)
void bindHarness(py::module_& m);      ///< compare, check, sweep, ensemble, write_report (harness_bindings.cpp)
void bindPlugins(py::module_& m);      ///< plugins() (plugin_bindings.cpp)

}  // namespace vroc::python
