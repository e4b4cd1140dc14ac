// SPDX-License-Identifier: MIT
#include "py_convert.h"

#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <cstdio>

#include "vroc/core/errors.h"

namespace vroc::python {

/// One row of vroc.EVENT_DTYPE.
struct EventRecord {
    double time;
    std::int32_t body_a;
    std::int32_t body_b;
    double point[3];
    double normal[3];
    double impulse;
};

}  // namespace vroc::python

namespace vroc::python {

std::vector<std::pair<std::string, std::string>> settingPairs(const py::handle& settings) {
    std::vector<std::pair<std::string, std::string>> out;
    if (settings.is_none()) return out;
    if (!py::isinstance<py::dict>(settings)) throw InputError("settings: expected a dict {key: value}");
    for (auto item : py::reinterpret_borrow<py::dict>(settings)) {
        if (!py::isinstance<py::str>(item.first)) throw InputError("settings: keys must be strings");
        const std::string key = item.first.cast<std::string>();
        const py::handle v = item.second;
        std::string text;
        if (py::isinstance<py::bool_>(v)) {
            text = v.cast<bool>() ? "true" : "false";
        } else if (py::isinstance<py::int_>(v)) {
            text = py::str(v).cast<std::string>();
        } else if (py::isinstance<py::float_>(v)) {
            char buf[40];
            std::snprintf(buf, sizeof buf, "%.17g", v.cast<double>());
            text = buf;
        } else if (py::isinstance<py::str>(v)) {
            text = v.cast<std::string>();
        } else {
            throw InputError("settings['" + key + "']: expected a bool, int, float or str, got " +
                             py::str(py::type::of(v).attr("__name__")).cast<std::string>());
        }
        out.emplace_back(key, text);
    }
    return out;
}

py::object settingValue(const SettingSpec& spec, const std::string& text) {
    Settings one(std::map<std::string, std::string>{{spec.key, text}});
    switch (spec.type) {
    case SettingSpec::Type::Integer: return py::int_(one.integer(spec.key));
    case SettingSpec::Type::Real: return py::float_(one.real(spec.key));
    case SettingSpec::Type::Boolean: return py::bool_(one.boolean(spec.key));
    case SettingSpec::Type::Choice: break;
    }
    return py::str(text);
}

py::dict settingsDict(const BackendInfo& info, const Settings& settings) {
    py::dict d;
    for (const SettingSpec& spec : info.settings) {
        const auto it = settings.values().find(spec.key);
        if (it != settings.values().end()) d[py::str(spec.key)] = settingValue(spec, it->second);
    }
    return d;
}

void registerEventDtype() { PYBIND11_NUMPY_DTYPE(EventRecord, time, body_a, body_b, point, normal, impulse); }

py::dtype eventDtype() { return py::dtype::of<EventRecord>(); }

py::array eventArray(const std::vector<CollisionEvent>& events) {
    py::array_t<EventRecord> a(static_cast<py::ssize_t>(events.size()));
    EventRecord* r = a.mutable_data();
    for (const CollisionEvent& e : events) {
        *r = {e.time, e.body_a, e.body_b, {e.point.x(), e.point.y(), e.point.z()},
              {e.normal.x(), e.normal.y(), e.normal.z()}, e.impulse};
        ++r;
    }
    return a;
}

Vec3 vec3From(const py::handle& value, const char* what) {
    try {
        const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
        if (a && a.ndim() == 1 && a.shape(0) == 3) return Vec3(a.at(0), a.at(1), a.at(2));
    } catch (const py::error_already_set&) {
    }
    throw InputError(std::string(what) + ": expected three numbers");
}

namespace {

py::array_t<double> numbers(std::initializer_list<double> values) {
    py::array_t<double> a(static_cast<py::ssize_t>(values.size()));
    std::copy(values.begin(), values.end(), a.mutable_data());
    return a;
}

}  // namespace

py::array_t<double> vec3Array(const Vec3& v) { return numbers({v.x(), v.y(), v.z()}); }

py::array_t<double> quatArray(const Quat& q) { return numbers({q.x(), q.y(), q.z(), q.w()}); }

}  // namespace vroc::python
