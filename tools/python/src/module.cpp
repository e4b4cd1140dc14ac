// SPDX-License-Identifier: MIT
// The extension module vroc._vroc, wrapped by the package vroc (tools/python/vroc/__init__.py).
// Errors: a caller's mistake (vroc::InputError, GeometryError) arrives as ValueError with the same
// one-line message `vroc` prints; a failure while running (RunError) as RuntimeError.
#include <exception>

#include "bindings.h"
#include "py_convert.h"
#include "vroc/core/build_info.h"
#include "vroc/core/errors.h"
#include "vroc/registration/register_backends.h"

namespace py = pybind11;

PYBIND11_MODULE(_vroc, m) {
    m.doc() = "VROC: physics backends on one scene, stepped, compared and checked (docs/python.md).";
    vroc::registration::registerBackends();
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const vroc::InputError& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        } catch (const vroc::GeometryError& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        } catch (const vroc::RunError& e) {
            PyErr_SetString(PyExc_RuntimeError, e.what());
        }
    });
    vroc::python::registerEventDtype();
    vroc::python::bindScene(m);
    vroc::python::bindBackends(m);
    vroc::python::bindSimulation(m);
    vroc::python::bindRollout(m);
    vroc::python::bindHarness(m);
    vroc::python::bindPlugins(m);
    m.attr("EVENT_DTYPE") = vroc::python::eventDtype();
    m.attr("STATE_WIDTH") = 13;
    const vroc::BuildInfo& build = vroc::buildInfo();
    m.attr("__version__") = build.version;
    py::dict info;
    info["version"] = build.version;
    info["commit"] = build.commit;
    info["compiler"] = build.compiler;
    info["flags"] = build.flags;
    m.attr("BUILD") = info;
}
