// SPDX-License-Identifier: MIT
// Strict loader for `vroc-scene/1` (docs/scene-format.md): top level, materials and bodies.
#include "vroc/core/scene_loader.h"

#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string_view>
#include <system_error>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "did_you_mean.h"
#include "file_bytes.h"
#include "scene_limits.h"
#include "scene_loader_internal.h"
#include "sha256.h"
#include "vroc/core/errors.h"

namespace vroc {

namespace {

constexpr const char* kFormat = "vroc-scene/1";

std::vector<Material> readMaterials(const JsonReader& r) {
    r.requireObject();
    std::vector<Material> materials;
    for (const std::string& name : r.keys()) {
        const JsonReader m = r.at(name);
        if (name.empty()) m.fail("expected a non-empty material name");
        m.requireObject({"restitution", "friction", "sound"});
        materials.push_back({name, m.at("restitution").inRange(0.0, 1.0, ""), m.at("friction").nonNegative("")});
        if (auto sound = m.find("sound")) materials.back().sound = readMaterialSound(*sound);
    }
    if (materials.empty()) r.fail("expected at least one material");
    return materials;
}

int findMaterial(const JsonReader& r, const std::vector<Material>& materials) {
    const std::string name = r.string();
    std::vector<std::string> names;
    for (std::size_t i = 0; i < materials.size(); ++i) {
        if (materials[i].name == name) return static_cast<int>(i);
        names.push_back(materials[i].name);
    }
    r.fail(fmt::format("unknown material `{}`; did you mean `{}`? (materials: {})", name,
                       nearestWord(name, names), fmt::format("{}", fmt::join(names, ", "))));
}

// Real bodies are the static model of the real world: they take no mass, inertia or velocity.
void rejectDynamicKeys(const JsonReader& body) {
    for (const char* key : {"mass", "inertia", "linear_velocity", "angular_velocity", "tracking"})
        if (auto v = body.find(key))
            v->fail(fmt::format("`{}` is not allowed on a real body (real bodies are static: infinite mass, "
                                "zero velocity); remove it or make the body \"virtual\" or \"tracked\"", key));
}

void rejectMassKeys(const JsonReader& body) {
    for (const char* key : {"mass", "inertia"})
        if (auto v = body.find(key))
            v->fail(fmt::format("`{}` is not allowed on a tracked body (collisions never move it: infinite "
                                "mass); remove it or make the body \"virtual\"", key));
}

TrackingSource readTracking(const JsonReader& r) {
    r.requireObject({"device", "sensor"});
    TrackingSource source;
    source.device = r.at("device").string();
    if (source.device.empty()) r.at("device").fail("expected a plugin spec such as \"udp:port=4242\"");
    if (auto s = r.find("sensor")) {
        const double sensor = s->inRange(0, 1e6, "");
        if (sensor != std::floor(sensor)) s->fail(fmt::format("expected an integer sensor index, got {}", s->describe()));
        source.sensor = static_cast<int>(sensor);
    }
    return source;
}

BodyRole readRole(const JsonReader& role) {
    const std::string name = role.string();
    if (name == "real") return BodyRole::Real;
    if (name == "virtual") return BodyRole::Virtual;
    if (name == "tracked") return BodyRole::Tracked;
    role.fail(fmt::format("expected \"real\", \"virtual\" or \"tracked\", got \"{}\"", name));
}

MassProperties readMassProperties(const JsonReader& body, const Shape& shape) {
    const double mass = body.at("mass").positiveIn(scene_limits::kMinMass, scene_limits::kMaxMass, " [kg]");
    MassProperties props;
    try {
        props = massProperties(shape, mass);
    } catch (const GeometryError& e) {
        body.at("shape").fail(fmt::format("cannot compute mass properties: {}", e.what()));
    }
    if (auto inertia = body.find("inertia")) props.inertia = readInertia(*inertia);
    return props;
}

Body readBody(const JsonReader& r, const std::vector<Material>& materials, const std::filesystem::path& base_dir) {
    r.requireObject({"name", "role", "material", "mass", "shape", "position", "orientation", "linear_velocity",
                     "angular_velocity", "inertia", "tracking"});
    Body body;
    body.name = r.at("name").string();
    if (body.name.empty()) r.at("name").fail("expected a non-empty body name");
    body.role = readRole(r.at("role"));
    body.material = findMaterial(r.at("material"), materials);
    body.shape = readShape(r.at("shape"), base_dir);
    body.pose.position = r.at("position").vec3Within(scene_limits::kMaxCoordinate, " [m]");
    if (auto q = r.find("orientation")) body.pose.orientation = q->quaternion();
    if (body.role == BodyRole::Real) {
        rejectDynamicKeys(r);
        return body;   // mass properties stay zero: static, infinite mass
    }
    if (body.role == BodyRole::Tracked) {
        rejectMassKeys(r);
        if (auto t = r.find("tracking")) body.tracking = readTracking(*t);
    } else {
        if (auto t = r.find("tracking"))
            t->fail("`tracking` is only allowed on a tracked body; make the body \"tracked\" or remove it");
        body.mass_properties = readMassProperties(r, body.shape);
    }
    if (auto v = r.find("linear_velocity")) body.linear_velocity = v->vec3Within(scene_limits::kMaxSpeed, " [m/s]");
    if (auto w = r.find("angular_velocity"))
        body.angular_velocity = w->vec3Within(scene_limits::kMaxAngularSpeed, " [rad/s]");
    return body;
}

std::vector<Body> readBodies(const JsonReader& r, const std::vector<Material>& materials,
                             const std::filesystem::path& base_dir) {
    if (r.arraySize() == 0) r.fail("expected at least one body");
    std::vector<Body> bodies;
    for (std::size_t i = 0; i < r.arraySize(); ++i) {
        const JsonReader b = r.element(i);
        bodies.push_back(readBody(b, materials, base_dir));
        for (std::size_t j = 0; j < i; ++j)
            if (bodies[j].name == bodies[i].name)
                b.at("name").fail(fmt::format("duplicate body name `{}` (also bodies[{}]); names must be unique",
                                              bodies[i].name, j));
    }
    return bodies;
}

Scene readScene(const JsonReader& root, const std::filesystem::path& base_dir) {
    root.requireObject();
    const JsonReader format = root.at("format");
    if (!format.isString() || format.string() != kFormat)
        format.fail(fmt::format("expected \"{}\", got {}", kFormat, format.describe()));
    root.requireObject({"format", "name", "description", "gravity", "frame_dt", "collision_distance",
                        "materials", "bodies"});
    Scene scene;
    scene.name = root.at("name").string();
    if (auto d = root.find("description")) scene.description = d->string();
    if (auto g = root.find("gravity")) scene.gravity = g->vec3Within(scene_limits::kMaxAcceleration, " [m/s^2]");
    if (auto dt = root.find("frame_dt"))
        scene.frame_dt = dt->positiveIn(scene_limits::kMinFrameDt, scene_limits::kMaxFrameDt, " [s]");
    if (auto cd = root.find("collision_distance"))
        scene.collision_distance =
            cd->positiveIn(scene_limits::kMinCollisionDistance, scene_limits::kMaxCollisionDistance, " [m]");
    scene.materials = readMaterials(root.at("materials"));
    scene.bodies = readBodies(root.at("bodies"), scene.materials, base_dir);
    return scene;
}

// An error message quotes names, keys and paths from the file, which JSON lets hold any control
// character: escaped as JSON writes them, so the message stays one line ("half_ext\nts" rather
// than a line break; found by tests/fuzz/scene_loader_fuzz, docs/fuzzing.md).
std::string oneLine(std::string_view message) {
    std::string out;
    for (const char c : message) {
        const auto u = static_cast<unsigned char>(c);
        if (u >= 0x20 && u != 0x7f) out += c;
        else if (c == '\n') out += "\\n";
        else if (c == '\r') out += "\\r";
        else if (c == '\t') out += "\\t";
        else out += fmt::format("\\u{:04x}", u);
    }
    return out;
}

}  // namespace

Scene loadSceneFromString(const std::string& json_text, const std::string& origin) {
    try {
        const JsonDocument document(json_text, origin);
        Scene scene = readScene(document.root(), std::filesystem::path(origin).parent_path());
        scene.source_sha256 = sha256Hex(json_text);
        return scene;
    } catch (const InputError& e) {
        throw InputError(oneLine(e.what()));
    }
}

Scene loadScene(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw InputError(fmt::format("{}: scene file not found or not a regular file (expected a readable vroc-scene/1 JSON file)", path));
    const std::optional<std::string> text = fileBytes(path);
    if (!text) throw InputError(fmt::format("{}: cannot read scene file", path));
    Scene scene = loadSceneFromString(*text, path);
    scene.source_path = path;
    return scene;
}

}  // namespace vroc
