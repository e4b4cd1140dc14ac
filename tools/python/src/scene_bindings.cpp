// SPDX-License-Identifier: MIT
// vroc.Scene, vroc.Body, vroc.Material and vroc.load_scene: the validated scene model, read-only.
#include <memory>
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "py_convert.h"
#include "state_rows.h"
#include "vroc/core/scene_loader.h"

namespace vroc::python {
namespace {

const char* roleName(BodyRole role) {
    switch (role) {
    case BodyRole::Real: return "real";
    case BodyRole::Virtual: return "virtual";
    case BodyRole::Tracked: return "tracked";
    }
    return "?";
}

}  // namespace

void bindScene(py::module_& m) {
    py::class_<Material>(m, "Material", "A scene material (read-only).")
        .def_readonly("name", &Material::name)
        .def_readonly("restitution", &Material::restitution, "Newton's coefficient [-]")
        .def_readonly("friction", &Material::friction, "Coulomb coefficient [-]")
        .def("__repr__", [](const Material& x) {
            return "<vroc.Material '" + x.name + "' e=" + py::repr(py::float_(x.restitution)).cast<std::string>() +
                   " mu=" + py::repr(py::float_(x.friction)).cast<std::string>() + ">";
        });

    py::class_<Body>(m, "Body", "A scene body at t = 0 (read-only). Arrays are copies.")
        .def_readonly("name", &Body::name)
        .def_property_readonly("role", [](const Body& b) { return roleName(b.role); }, "'real', 'virtual' or 'tracked'")
        .def_readonly("material", &Body::material, "index into Scene.materials")
        .def_property_readonly("shape", [](const Body& b) { return b.shape.kindName(); },
                               "'sphere', 'box', 'hull' or 'compound'")
        .def_property_readonly("radius", [](const Body& b) { return b.shape.radius; }, "[m] spheres; 0 otherwise")
        .def_property_readonly("half_extents", [](const Body& b) { return vec3Array(b.shape.half_extents); },
                               "[m] boxes; zeros otherwise")
        .def_property_readonly("bounding_radius", [](const Body& b) { return b.shape.boundingRadius(); }, "[m]")
        .def_property_readonly("position", [](const Body& b) { return vec3Array(b.pose.position); }, "[m] body frame origin")
        .def_property_readonly("orientation", [](const Body& b) { return quatArray(b.pose.orientation); }, "x y z w")
        .def_property_readonly("linear_velocity", [](const Body& b) { return vec3Array(b.linear_velocity); },
                               "[m/s] of the centre of mass")
        .def_property_readonly("angular_velocity", [](const Body& b) { return vec3Array(b.angular_velocity); }, "[rad/s]")
        .def_property_readonly("mass", [](const Body& b) { return b.mass_properties.mass; }, "[kg] (virtual bodies)")
        .def_property_readonly("center_of_mass", [](const Body& b) { return vec3Array(b.mass_properties.center_of_mass); },
                               "[m] body frame")
        .def("__repr__", [](const Body& b) {
            return std::string("<vroc.Body '") + b.name + "' " + roleName(b.role) + " " + b.shape.kindName() + ">";
        });

    py::class_<Scene, std::shared_ptr<Scene>>(m, "Scene",
                                              "A validated scene (vroc-scene/1). Load with vroc.load_scene(path) or "
                                              "Scene.from_json(text); bad input raises ValueError naming file, field "
                                              "and what was expected.")
        .def_static(
            "from_json",
            [](const std::string& text, const std::string& origin) {
                return std::make_shared<Scene>(loadSceneFromString(text, origin));
            },
            py::arg("text"), py::arg("origin") = "<string>", "Parses a scene from JSON text; `origin` names it in errors.")
        .def_readonly("name", &Scene::name)
        .def_readonly("description", &Scene::description)
        .def_readonly("source_path", &Scene::source_path)
        .def_readonly("source_sha256", &Scene::source_sha256)
        .def_property_readonly("gravity", [](const Scene& s) { return vec3Array(s.gravity); }, "[m/s^2]")
        .def_readonly("frame_dt", &Scene::frame_dt, "[s] default frame step")
        .def_readonly("collision_distance", &Scene::collision_distance, "[m]")
        .def_readonly("bodies", &Scene::bodies, "list of Body, indexed as in every array")
        .def_readonly("materials", &Scene::materials)
        .def_property_readonly("body_names", [](const Scene& s) {
            py::list names;
            for (const Body& b : s.bodies) names.append(b.name);
            return names;
        })
        .def_property_readonly(
            "virtual", [](const Scene& s) {
                py::array_t<bool> a(static_cast<py::ssize_t>(s.bodies.size()));
                for (std::size_t i = 0; i < s.bodies.size(); ++i) a.mutable_data()[i] = s.bodies[i].isDynamic();
                return a;
            },
            "bool mask (N,): the virtual (dynamic) bodies")
        .def("find_body", &Scene::findBody, py::arg("name"), "index of a body by name, -1 if absent")
        .def(
            "initial_state",
            [](const Scene& s) {
                py::array_t<double> a({static_cast<py::ssize_t>(s.bodies.size()), static_cast<py::ssize_t>(kStateWidth)});
                for (std::size_t i = 0; i < s.bodies.size(); ++i) {
                    const Body& b = s.bodies[i];
                    writeStateRow({b.pose, b.linear_velocity, b.angular_velocity}, a.mutable_data() + i * kStateWidth);
                }
                return a;
            },
            "(N, 13) array of the file's state: position, orientation x y z w, linear and angular velocity")
        .def("__len__", [](const Scene& s) { return s.bodies.size(); })
        .def("__repr__", [](const Scene& s) {
            return "<vroc.Scene '" + s.name + "' " + std::to_string(s.bodies.size()) + " bodies>";
        });

    m.def(
        "load_scene", [](const std::string& path) { return std::make_shared<Scene>(loadScene(path)); }, py::arg("path"),
        "Loads and validates a scene file (vroc-scene/1 JSON). Raises ValueError with the loader's message.");
}

}  // namespace vroc::python
