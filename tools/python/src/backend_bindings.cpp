// SPDX-License-Identifier: MIT
// vroc.backends(): every backend of this build with its version, capabilities, deviations from its
// engine's defaults and declared settings, as Python objects.
#include <pybind11/stl.h>

#include "bindings.h"
#include "py_convert.h"
#include "vroc/core/backend_registry.h"

namespace vroc::python {
namespace {

const char* typeName(SettingSpec::Type t) {
    switch (t) {
    case SettingSpec::Type::Integer: return "int";
    case SettingSpec::Type::Real: return "float";
    case SettingSpec::Type::Boolean: return "bool";
    case SettingSpec::Type::Choice: return "choice";
    }
    return "?";
}

py::dict capabilitiesDict(const BackendCapabilities& c) {
    py::dict d;
    d["sphere"] = supportName(c.sphere);
    d["box"] = supportName(c.box);
    d["hull"] = supportName(c.hull);
    d["compound"] = supportName(c.compound);
    d["restitution"] = supportName(c.restitution);
    d["tracked"] = supportName(c.tracked);
    d["friction"] = frictionName(c.friction);
    d["continuous_collision"] = c.continuous_collision;
    d["deterministic"] = c.deterministic;
    d["precision"] = c.precision;
    d["notes"] = c.notes;
    return d;
}

}  // namespace

void bindBackends(py::module_& m) {
    py::class_<SettingSpec>(m, "SettingSpec", "One declared backend setting.")
        .def_readonly("key", &SettingSpec::key, "'<backend>.<name>'")
        .def_property_readonly("type", [](const SettingSpec& s) { return typeName(s.type); }, "int, float, bool or choice")
        .def_property_readonly("default", [](const SettingSpec& s) { return settingValue(s, s.default_value); })
        .def_readonly("min", &SettingSpec::min)
        .def_readonly("max", &SettingSpec::max)
        .def_readonly("choices", &SettingSpec::choices)
        .def_readonly("help", &SettingSpec::help)
        .def("__repr__", [](const SettingSpec& s) { return "<vroc.SettingSpec " + s.describe() + ">"; });

    // BackendInfo lives in the registry for the life of the process: handed out by reference.
    py::class_<BackendInfo>(m, "BackendInfo", "A registered backend.")
        .def_readonly("name", &BackendInfo::name)
        .def_readonly("description", &BackendInfo::description)
        .def_readonly("version", &BackendInfo::version)
        .def_property_readonly("capabilities", [](const BackendInfo& b) { return capabilitiesDict(b.capabilities); })
        .def_readonly("deviations", &BackendInfo::deviations, "settings that differ from the engine's own defaults, with why")
        .def_readonly("settings", &BackendInfo::settings, "list of SettingSpec")
        .def_property_readonly("defaults", [](const BackendInfo& b) { return settingsDict(b, resolveSettings(b.settings, {})); },
                               "{key: default value}")
        .def("__repr__", [](const BackendInfo& b) { return "<vroc.BackendInfo " + b.name + " (" + b.version + ")>"; });

    m.def(
        "backends",
        [] {
            py::list out;
            for (const BackendInfo* info : BackendRegistry::global().all())
                out.append(py::cast(info, py::return_value_policy::reference));
            return out;
        },
        "Every backend of this build, in name order (BackendInfo objects).");
    m.def(
        "backend", [](const std::string& name) { return &BackendRegistry::global().require(name); }, py::arg("name"),
        py::return_value_policy::reference, "One backend by name; ValueError listing the known ones if unknown.");
}

}  // namespace vroc::python
