// SPDX-License-Identifier: MIT
// Conversions between Python values and the project's types, one home for every binding file.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "vroc/core/backend.h"

namespace vroc::python {

namespace py = pybind11;

/// A settings dict {key: value} -> "key=value" pairs: bool -> true/false, int as it is, float with
/// 17 significant digits (exact), str as it is. Keys are taken as they are (see fullSettingKey).
/// Throws InputError for another value type, naming the key.
std::vector<std::pair<std::string, std::string>> settingPairs(const py::handle& settings);

/// A resolved setting's text -> int, float, bool or str by its declared type.
py::object settingValue(const SettingSpec& spec, const std::string& text);
/// Every resolved setting of a backend as {key: typed value}.
py::dict settingsDict(const BackendInfo& info, const Settings& settings);

/// Collision events -> a structured array of dtype vroc.EVENT_DTYPE
/// (time f8, body_a i4, body_b i4, point 3f8, normal 3f8, impulse f8).
py::array eventArray(const std::vector<CollisionEvent>& events);
/// Registers the event dtype with pybind11: once, at module import, before eventArray.
void registerEventDtype();
/// The dtype itself.
py::dtype eventDtype();

/// A 3-vector from any sequence of three numbers; InputError naming `what` otherwise.
Vec3 vec3From(const py::handle& value, const char* what);
py::array_t<double> vec3Array(const Vec3& v);
/// x y z w, the files' order.
py::array_t<double> quatArray(const Quat& q);

}  // namespace vroc::python
