// SPDX-License-Identifier: MIT
// One test per bad-input class of issue 3 ("Bad input"): each asserts that the loader throws
// InputError with one line naming the file, the field (JSON path, or line and column for syntax
// errors) and what was expected. Expected line/column numbers are counted by hand in the text.
#include <gtest/gtest.h>

#include <initializer_list>
#include <string>

#include "vroc/core/errors.h"
#include "vroc/core/scene_loader.h"

namespace vroc {
namespace {

const std::string kDataDir = std::string(VROC_SOURCE_DIR) + "/tests/data/scenes";
const std::string kOrigin = kDataDir + "/inline.json";

// The message of the InputError that loading `text` throws ("" and a test failure if none).
std::string errorOf(const std::string& text) {
    try {
        loadSceneFromString(text, kOrigin);
    } catch (const InputError& e) {
        return e.what();
    } catch (const std::exception& e) {
        ADD_FAILURE() << "expected InputError, got another exception: " << e.what();
        return "";
    }
    ADD_FAILURE() << "expected InputError for:\n" << text;
    return "";
}

// Every message: starts with the file, is one line, and contains each of `parts`.
void expectMessage(const std::string& message, std::initializer_list<std::string> parts,
                   const std::string& file = kOrigin) {
    EXPECT_EQ(message.rfind(file, 0), 0u) << "message does not start with the file: " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "message is not one line: " << message;
    for (const std::string& p : parts) EXPECT_NE(message.find(p), std::string::npos) << "'" << p << "' not in: " << message;
}

void expectError(const std::string& text, std::initializer_list<std::string> parts) {
    expectMessage(errorOf(text), parts);
}

const std::string kMaterials = R"("materials": {"rubber": {"restitution": 0.5, "friction": 0.8}})";
const std::string kFloor = R"({"name": "floor", "role": "real", "material": "rubber", "position": [0, 0, 0],
                               "shape": {"box": {"half_extents": [1, 1, 1]}}})";

std::string sceneWith(const std::string& bodies, const std::string& top = "", const std::string& materials = kMaterials) {
    return R"({"format": "vroc-scene/1", "name": "t", )" + top + materials + R"(, "bodies": [)" + bodies + "]}";
}

std::string sceneWithMaterial(const std::string& rubber) {
    return sceneWith(kFloor, "", R"("materials": {"rubber": )" + rubber + "}");
}

// A virtual ball body; `extra` adds keys, `shape` and `mass` replace the defaults.
std::string ball(const std::string& extra = "", const std::string& shape = R"({"sphere": {"radius": 0.1}})",
                 const std::string& mass = "1") {
    return R"({"name": "ball", "role": "virtual", "material": "rubber", "mass": )" + mass +
           R"(, "position": [0, 0, 1], "shape": )" + shape + extra + "}";
}

std::string withBall(const std::string& extra = "", const std::string& shape = R"({"sphere": {"radius": 0.1}})",
                     const std::string& mass = "1") {
    return sceneWith(kFloor + ", " + ball(extra, shape, mass));
}

TEST(SceneBadInput, ValidBaseSceneLoads) {
    // The fixtures below each break one thing in this scene.
    EXPECT_NO_THROW(loadSceneFromString(withBall(), kOrigin));
}

TEST(SceneBadInput, MissingFile) {
    const std::string path = kDataDir + "/no_such_scene.json";
    try {
        loadScene(path);
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        expectMessage(e.what(), {"not found", "vroc-scene/1"}, path);
    }
    try {
        loadScene(kDataDir);   // a directory is not a scene file
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        expectMessage(e.what(), {"not a regular file"}, kDataDir);
    }
}

TEST(SceneBadInput, TruncatedJsonGivesLineAndColumn) {
    // Line 3 is `  "bodies": [` (13 characters): the input ends just after it, at column 14.
    const std::string text = "{\n  \"format\": \"vroc-scene/1\",\n  \"bodies\": [";
    expectError(text, {kOrigin + ":3:14: invalid JSON", "unexpected end of input"});
}

TEST(SceneBadInput, InvalidJsonGivesLineAndColumn) {
    // Line 3 is `  "name": @,`: the '@' is at column 11.
    const std::string text = "{\n  \"format\": \"vroc-scene/1\",\n  \"name\": @,\n}";
    expectError(text, {kOrigin + ":3:11: invalid JSON", "syntax error"});
    // A trailing comma (not JSON): line 2 is `  "name": "t",` and the '}' on line 3 is at column 1.
    expectError("{\"format\": \"vroc-scene/1\",\n  \"name\": \"t\",\n}", {kOrigin + ":3:1: invalid JSON"});
    // Empty input.
    expectError("", {kOrigin + ":1:1: invalid JSON"});
}

TEST(SceneBadInput, DuplicateJsonKey) {
    expectError(withBall(R"(, "mass": 2)"), {"bodies[1]: duplicate key `mass`"});
}

TEST(SceneBadInput, WrongFormat) {
    expectError(R"({"format": "vroc-scene/2", "name": "t"})",
                {": format: expected \"vroc-scene/1\"", "\"vroc-scene/2\""});
    expectError(R"({"format": 1})", {": format: expected \"vroc-scene/1\", got 1"});
    expectError(R"({"name": "t"})", {": missing required key `format`"});
    expectError(R"([1, 2])", {"expected an object, got an array"});
}

TEST(SceneBadInput, UnknownKeyWithSuggestion) {
    // In a material, a body, a shape and at top level.
    expectError(sceneWithMaterial(R"({"restituion": 0.5, "friction": 0.8})"),
                {"materials.rubber: unknown key `restituion`; did you mean `restitution`?"});
    expectError(withBall(R"(, "angular_velocty": [0, 0, 1])"),
                {"bodies[1]: unknown key `angular_velocty`; did you mean `angular_velocity`?"});
    expectError(withBall("", R"({"sphere": {"raduis": 0.1}})"),
                {"bodies[1].shape.sphere: unknown key `raduis`; did you mean `radius`?"});
    expectError(withBall("", R"({"spere": {"radius": 0.1}})"),
                {"bodies[1].shape: unknown key `spere`; did you mean `sphere`?"});
    expectError(sceneWith(kFloor, R"("gravty": [0, 0, -9.81], )"), {": unknown key `gravty`; did you mean `gravity`?"});
}

TEST(SceneBadInput, MissingRequiredKey) {
    expectError(sceneWith(R"({"name": "floor", "role": "real", "material": "rubber", "position": [0, 0, 0]})"),
                {"bodies[0]: missing required key `shape`"});
    expectError(sceneWith(R"({"name": "b", "role": "virtual", "material": "rubber", "position": [0, 0, 0],
                              "shape": {"sphere": {"radius": 1}}})"),
                {"bodies[0]: missing required key `mass`"});
    expectError(sceneWithMaterial(R"({"restitution": 0.5})"),
                {"materials.rubber: missing required key `friction`"});
    expectError(R"({"format": "vroc-scene/1", "name": "t", )" + kMaterials + "}", {": missing required key `bodies`"});
}

TEST(SceneBadInput, WrongType) {
    expectError(withBall("", R"({"sphere": {"radius": 0.1}})", R"("heavy")"),
                {"bodies[1].mass: expected a number, got the string \"heavy\""});
    expectError(withBall(R"(, "linear_velocity": [1, 2])"),
                {"bodies[1].linear_velocity: expected an array of 3 numbers [x, y, z], got an array"});
    expectError(withBall(R"(, "angular_velocity": [1, true, 3])"),
                {"bodies[1].angular_velocity[1]: expected a number, got true"});
    expectError(sceneWith(kFloor, R"("frame_dt": "1/60", )"), {": frame_dt: expected a number, got the string"});
    expectError(R"({"format": "vroc-scene/1", "name": 5})", {": name: expected a string, got 5"});
    expectError(withBall("", R"({"sphere": [0.1]})"), {"bodies[1].shape.sphere: expected an object, got an array"});
}

TEST(SceneBadInput, NonFiniteNumber) {
    // JSON has no NaN or Infinity literal; a number too large for a double (1e999) is rejected
    // at parse time with the line and column where it starts. Line 2 is `"gravity": [0, 0, 1e999],`:
    // '1e999' starts at column 19.
    const std::string text = "{\"format\": \"vroc-scene/1\",\n\"gravity\": [0, 0, 1e999],\n\"name\": \"t\"}";
    expectError(text, {kOrigin + ":2:19: invalid JSON", "number overflow parsing '1e999'", "not a finite double"});
    expectError("{\"mass\": -1e999}", {kOrigin + ":1:10: invalid JSON", "'-1e999'"});
    // NaN / Infinity words are simply invalid JSON.
    expectError("{\"mass\": NaN}", {kOrigin + ":1:10: invalid JSON"});
    expectError("{\"mass\": Infinity}", {kOrigin + ":1:10: invalid JSON"});
}

TEST(SceneBadInput, ZeroOrNegativeMass) {
    expectError(withBall("", R"({"sphere": {"radius": 0.1}})", "0"), {"bodies[1].mass: expected a number > 0 [kg], got 0"});
    expectError(withBall("", R"({"sphere": {"radius": 0.1}})", "-2.5"), {"bodies[1].mass: expected a number > 0 [kg], got -2.5"});
}

TEST(SceneBadInput, MassOnARealBody) {
    expectError(sceneWith(R"({"name": "floor", "role": "real", "material": "rubber", "mass": 5, "position": [0, 0, 0],
                              "shape": {"box": {"half_extents": [1, 1, 1]}}})"),
                {"bodies[0].mass: `mass` is not allowed on a real body"});
    expectError(sceneWith(R"({"name": "floor", "role": "real", "material": "rubber", "linear_velocity": [1, 0, 0],
                              "position": [0, 0, 0], "shape": {"box": {"half_extents": [1, 1, 1]}}})"),
                {"bodies[0].linear_velocity: `linear_velocity` is not allowed on a real body"});
}

TEST(SceneBadInput, TrackedBodyTakesNoMassAndOnlyItHasTracking) {
    const std::string pad = R"({"name": "pad", "role": "tracked", "material": "rubber", "position": [0, 0, 0],
                              "shape": {"box": {"half_extents": [1, 1, 1]}})";
    expectError(sceneWith(pad + R"(, "mass": 2})"), {"bodies[0].mass: `mass` is not allowed on a tracked body"});
    expectError(sceneWith(pad + R"(, "inertia": [1, 1, 1]})"), {"bodies[0].inertia: `inertia` is not allowed on a tracked body"});
    expectError(sceneWith(pad + R"(, "tracking": {"device": ""}})"), {"bodies[0].tracking.device: expected a plugin spec"});
    expectError(sceneWith(pad + R"(, "tracking": {"device": "udp", "sensor": 1.5}})"),
                {"bodies[0].tracking.sensor: expected an integer sensor index, got"});
    expectError(sceneWith(pad + R"(, "tracking": {"device": "udp", "sensor": -1}})"), {"bodies[0].tracking.sensor:"});
    expectError(sceneWith(pad + R"(, "tracking": {"device": "udp", "sesnor": 1}})"),
                {"bodies[0].tracking: unknown key `sesnor`; did you mean `sensor`?"});
    expectError(sceneWith(R"({"name": "floor", "role": "real", "material": "rubber", "position": [0, 0, 0],
                              "shape": {"box": {"half_extents": [1, 1, 1]}}, "tracking": {"device": "udp"}})"),
                {"bodies[0].tracking: `tracking` is not allowed on a real body"});
    expectError(withBall(R"(, "tracking": {"device": "udp"})"),
                {"bodies[1].tracking: `tracking` is only allowed on a tracked body"});
}

// Magnitudes outside the accepted ranges (docs/scene-format.md) are rejected with the field named,
// so no backend starts from a state it cannot represent (a 1e308 position once loaded, and then
// two backends gave two answers).
TEST(SceneBadInput, ValuesOutsideTheAcceptedRanges) {
    const std::string range = "(the accepted range, docs/scene-format.md)";
    expectError(withBall(R"(, "linear_velocity": [0, 2e4, 0])"),
                {"bodies[1].linear_velocity[1]: expected a number in [-10000, 10000] [m/s]", range, "got 20000"});
    expectError(withBall(R"(, "angular_velocity": [0, 0, -1e308])"),
                {"bodies[1].angular_velocity[2]: expected a number in [-100000, 100000] [rad/s]", "got -1e+308"});
    expectError(withBall("", R"({"sphere": {"radius": 0.1}})", "1e10"),
                {"bodies[1].mass: expected a number in [1e-09, 1000000000] [kg]", "got 10000000000"});
    expectError(withBall("", R"({"sphere": {"radius": 0.1}})", "1e-12"), {"bodies[1].mass: expected a number in"});
    expectError(withBall("", R"({"sphere": {"radius": 1e-7}})"),
                {"bodies[1].shape.sphere.radius: expected a number in [1e-06, 1000000] [m]"});
    expectError(withBall("", R"({"box": {"half_extents": [0.1, 2e6, 0.1]}})"),
                {"bodies[1].shape.box.half_extents[1]: expected a number in [1e-06, 1000000] [m]"});
    expectError(withBall("", R"({"hull": {"points": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1e300]]}})"),
                {"bodies[1].shape.hull.points[3][2]: expected a number in [-1000000, 1000000] [m]"});
    expectError(withBall("", R"({"mesh": {"file": "tetra.obj", "scale": 1e10}})"),
                {"bodies[1].shape.mesh.scale: expected a number in [1e-09, 1000000000]"});
    expectError(withBall("", R"({"mesh": {"file": "tetra.obj", "scale": 1e8}})"),
                {"bodies[1].shape.mesh.file: mesh", "outside the accepted range of +-1000000 m per coordinate"});
    expectError(withBall("", R"({"sphere": {"radius": 0.1}}, "inertia": [1, 1e31, 1])"),
                {"bodies[1].inertia[1]: expected a number in [1e-30, 1e+30] [kg m^2]"});
    expectError(sceneWith(R"({"name": "floor", "role": "real", "material": "rubber", "position": [1e308, 0, 0],
                              "shape": {"box": {"half_extents": [1, 1, 1]}}})"),
                {"bodies[0].position[0]: expected a number in [-1000000, 1000000] [m]", "got 1e+308"});
    expectError(sceneWith(kFloor, R"("gravity": [0, 0, -1e5], )"), {": gravity[2]: expected a number in [-10000, 10000] [m/s^2]"});
    expectError(sceneWith(kFloor, R"("frame_dt": 60, )"), {": frame_dt: expected a number in [1e-06, 10] [s]"});
    expectError(sceneWith(kFloor, R"("collision_distance": 2, )"),
                {": collision_distance: expected a number in [1e-09, 1] [m]"});
}

TEST(SceneBadInput, NonPositiveRadiusOrExtent) {
    expectError(withBall("", R"({"sphere": {"radius": 0}})"), {"bodies[1].shape.sphere.radius: expected a number > 0 [m], got 0"});
    expectError(withBall("", R"({"sphere": {"radius": -0.1}})"), {"bodies[1].shape.sphere.radius: expected a number > 0 [m], got -0.1"});
    expectError(withBall("", R"({"box": {"half_extents": [1, -0.5, 1]}})"),
                {"bodies[1].shape.box.half_extents[1]: expected a number > 0 [m], got -0.5"});
    expectError(withBall("", R"({"box": {"half_extents": [0, 1, 1]}})"),
                {"bodies[1].shape.box.half_extents[0]: expected a number > 0 [m], got 0"});
    expectError(withBall("", R"({"mesh": {"file": "tetra.obj", "scale": [1, 0, 1]}})"),
                {"bodies[1].shape.mesh.scale[1]: expected a number > 0, got 0"});
}

TEST(SceneBadInput, DegenerateHull) {
    expectError(withBall("", R"({"hull": {"points": [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}})"),
                {"bodies[1].shape.hull.points: degenerate hull of 3 points", "expected at least 4 points not all in one plane"});
    expectError(withBall("", R"({"hull": {"points": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0], [0.5, 0.5, 0]]}})"),
                {"bodies[1].shape.hull.points: degenerate hull of 5 points"});
    expectError(withBall("", R"({"mesh": {"file": "flat.obj"}})"),
                {"bodies[1].shape.mesh.file: degenerate hull of mesh", "flat.obj"});
}

TEST(SceneBadInput, MissingMeshFile) {
    expectError(withBall("", R"({"mesh": {"file": "meshes/nope.obj"}})"),
                {"bodies[1].shape.mesh.file: mesh file '" + kDataDir + "/meshes/nope.obj' not found",
                 "relative to the scene file"});
}

TEST(SceneBadInput, UnreadableMesh) {
    expectError(withBall("", R"({"mesh": {"file": "truncated.stl"}})"),
                {"bodies[1].shape.mesh.file: cannot read mesh file '" + kDataDir + "/truncated.stl'",
                 "expected OBJ, STL, PLY or glTF"});
    expectError(withBall("", R"({"mesh": {"file": "not_a_mesh.xyz"}})"),
                {"bodies[1].shape.mesh.file: cannot read mesh file '" + kDataDir + "/not_a_mesh.xyz'"});
}

// Found by tests/fuzz/mesh_import_fuzz (docs/fuzzing.md): assimp 5.2.5 never returns from a PLY
// file without end_header (it loops, allocating); without the loader's check this test hangs until
// CTest's timeout.
TEST(SceneBadInput, PlyHeaderWithoutEnd) {
    expectError(withBall("", R"({"mesh": {"file": "no_end_header.ply"}})"),
                {"bodies[1].shape.mesh.file: cannot read mesh file '" + kDataDir + "/no_end_header.ply'",
                 "as PLY: line 7: unknown header keyword `0` (expected comment, obj_info, format, element, property or "
                 "end_header)"});
}

// Found by tests/fuzz/mesh_import_fuzz in CI (docs/fuzzing.md): assimp 5.2.5 frees memory it does
// not own, or reads past its buffers, on a malformed PLY header (a second `ply` line inside it; a
// line of binary bytes). The loader checks the header's grammar first; each file here reaches
// assimp only if that check is gone, and the first one then crashes the test under the sanitizers.
TEST(SceneBadInput, MalformedPlyHeadersAreRefusedWithTheirLine) {
    const std::string prefix = "bodies[1].shape.mesh.file: cannot read mesh file '" + kDataDir;
    expectError(withBall("", R"({"mesh": {"file": "ply_header_second_magic.ply"}})"),
                {prefix + "/ply_header_second_magic.ply' as PLY: line 6: unknown header keyword `ply`"});
    expectError(withBall("", R"({"mesh": {"file": "ply_without_z.ply"}})"),
                {prefix + "/ply_without_z.ply' as PLY: element vertex has no scalar property `z`"});
    expectError(
        withBall("", R"({"mesh": {"file": "ply_count_beyond_file.ply"}})"),
        {prefix + "/ply_count_beyond_file.ply' as PLY: line 3: element `vertex` declares 4000000000 instances"});
    expectError(
        withBall("", R"({"mesh": {"file": "ply_header_binary_bytes.ply"}})"),
        {prefix + "/ply_header_binary_bytes.ply' as PLY: line 6: byte 0x9b in the header (expected printable ASCII)"});
}

// Also found by mesh_import_fuzz: assimp reads past its buffers on a face index beyond the vertices
// (binary, from the fuzzer) and on a binary body shorter than the header declares; an ASCII list
// with fewer numbers than its count is refused the same way.
TEST(SceneBadInput, MalformedPlyBodiesAreRefusedWithTheirElement) {
    const std::string prefix = "bodies[1].shape.mesh.file: cannot read mesh file '" + kDataDir;
    expectError(
        withBall("", R"({"mesh": {"file": "ply_face_index_beyond_vertices.ply"}})"),
        {prefix + "/ply_face_index_beyond_vertices.ply' as PLY: element `face` #10: vertex index 67108871 is not one "
                  "of the 8 vertices"});
    expectError(withBall("", R"({"mesh": {"file": "ply_binary_truncated.ply"}})"),
                {prefix + "/ply_binary_truncated.ply' as PLY: element `vertex` #3: the file ends inside it"});
    expectError(
        withBall("", R"({"mesh": {"file": "ply_ascii_list_short.ply"}})"),
        {prefix + "/ply_ascii_list_short.ply' as PLY: element `face` #0 (line 14): list `vertex_indices` declares 3 "
                  "numbers, the line has 2"});
}

// Found by mesh_import_fuzz: assimp allocates what a GLB header declares (here 895 MB for a
// 163-byte file; over 2 GB in all) before it reads the file.
TEST(SceneBadInput, GlbDeclaringMoreThanTheFileIsRefused) {
    expectError(
        withBall("", R"({"mesh": {"file": "glb_length_beyond_file.glb"}})"),
        {"bodies[1].shape.mesh.file: cannot read mesh file '" + kDataDir +
         "/glb_length_beyond_file.glb' as binary glTF: header length 895774108 is more than the file's 163 bytes"});
    EXPECT_NO_THROW(loadSceneFromString(withBall("", R"({"mesh": {"file": "cube.glb"}})"), kOrigin));
}

// The check refuses nothing a PLY writer produces: the fixtures (ASCII with faces, binary) load.
TEST(SceneBadInput, WellFormedPlyHeadersPass) {
    for (const char* file : {"tetra.ply", "tetra_binary.ply"}) {
        const std::string json = withBall("", std::string(R"({"mesh": {"file": ")") + file + R"("}})");
        EXPECT_NO_THROW(loadSceneFromString(json, kOrigin)) << file;
    }
}

// Found by tests/fuzz/scene_loader_fuzz (docs/fuzzing.md): a key or name with a JSON escape such
// as \n made the message two lines. Control characters are shown escaped, as JSON writes them.
TEST(SceneBadInput, ControlCharactersInKeysAndNamesStayOnOneLine) {
    expectError(withBall("", R"({"box": {"half_ext\nts": [0.5, 0.01, 0.01]}})"),
                {"bodies[1].shape.box", "unknown key `half_ext\\nts`"});
    expectError(sceneWith(R"({"name": "floor", "role": "real", "material": "rub\tber\u0001", "position": [0, 0, 0],
                              "shape": {"sphere": {"radius": 1}}})"),
                {"bodies[0].material: unknown material `rub\\tber\\u0001`"});
}

TEST(SceneBadInput, UnknownMaterial) {
    expectError(sceneWith(kFloor + R"(, {"name": "ball", "role": "virtual", "material": "rubbr", "mass": 1,
                                        "position": [0, 0, 1], "shape": {"sphere": {"radius": 0.1}}})"),
                {"bodies[1].material: unknown material `rubbr`; did you mean `rubber`?"});
}

TEST(SceneBadInput, DuplicateBodyName) {
    expectError(sceneWith(kFloor + ", " + kFloor), {"bodies[1].name: duplicate body name `floor` (also bodies[0])"});
}

TEST(SceneBadInput, ZeroQuaternion) {
    expectError(withBall(R"(, "orientation": [0, 0, 0, 0])"),
                {"bodies[1].orientation: expected a non-zero quaternion [x, y, z, w]", "got |q| = 0"});
    expectError(withBall(R"(, "orientation": [1e-10, 0, 0, 0])"), {"bodies[1].orientation: expected a non-zero quaternion"});
    expectError(withBall(R"(, "orientation": [0, 0, 1])"), {"bodies[1].orientation: expected a quaternion [x, y, z, w]"});
}

TEST(SceneBadInput, RestitutionOutsideUnitIntervalOrNegativeFriction) {
    const auto withMaterial = sceneWithMaterial;
    expectError(withMaterial(R"({"restitution": 1.5, "friction": 0.5})"),
                {"materials.rubber.restitution: expected a number in [0, 1], got 1.5"});
    expectError(withMaterial(R"({"restitution": -0.1, "friction": 0.5})"),
                {"materials.rubber.restitution: expected a number in [0, 1], got -0.1"});
    expectError(withMaterial(R"({"restitution": 0.5, "friction": -0.2})"),
                {"materials.rubber.friction: expected a number >= 0, got -0.2"});
}

TEST(SceneBadInput, NonPositiveFrameDtOrCollisionDistance) {
    expectError(sceneWith(kFloor, R"("frame_dt": 0, )"), {": frame_dt: expected a number > 0 [s], got 0"});
    expectError(sceneWith(kFloor, R"("frame_dt": -0.01, )"), {": frame_dt: expected a number > 0 [s], got -0.01"});
    expectError(sceneWith(kFloor, R"("collision_distance": 0, )"), {": collision_distance: expected a number > 0 [m], got 0"});
}

TEST(SceneBadInput, ShapeMustBeExactlyOneKind) {
    expectError(withBall("", R"({"sphere": {"radius": 0.1}, "box": {"half_extents": [1, 1, 1]}})"),
                {"bodies[1].shape: expected exactly one of sphere, box, hull, mesh, compound; got `sphere`, `box`"});
    expectError(withBall("", "{}"), {"bodies[1].shape: expected exactly one of", "got none"});
    expectError(withBall("", R"({"mesh": {"file": "tetra.obj", "mode": "convex"}})"),
                {"bodies[1].shape.mesh.mode: expected \"hull\" or \"parts\", got \"convex\""});
    expectError(withBall("", R"({"compound": {"parts": []}})"), {"bodies[1].shape.compound.parts: expected at least one part"});
}

TEST(SceneBadInput, BadRoleAndEmptyLists) {
    expectError(sceneWith(R"({"name": "floor", "role": "ghost", "material": "rubber", "position": [0, 0, 0],
                              "shape": {"box": {"half_extents": [1, 1, 1]}}})"),
                {"bodies[0].role: expected \"real\", \"virtual\" or \"tracked\", got \"ghost\""});
    expectError(sceneWith(""), {": bodies: expected at least one body"});
    expectError(R"({"format": "vroc-scene/1", "name": "t", "materials": {}, "bodies": [1]})",
                {": materials: expected at least one material"});
}

TEST(SceneBadInput, InvalidInertiaOverride) {
    expectError(withBall(R"(, "inertia": [1, 1, 0])"), {"bodies[1].inertia[2]: expected a number > 0 [kg m^2], got 0"});
    expectError(withBall(R"(, "inertia": [1, 1, 3])"), {"bodies[1].inertia: principal moments", "triangle inequality"});
    expectError(withBall(R"(, "inertia": [[1, 0.5, 0], [0, 1, 0], [0, 0, 1]])"),
                {"bodies[1].inertia: expected a symmetric matrix"});
    // Symmetric but indefinite: eigenvalues of [[1, 2], [2, 1]] are 3 and -1.
    expectError(withBall(R"(, "inertia": [[1, 2, 0], [2, 1, 0], [0, 0, 1]])"),
                {"bodies[1].inertia: expected a positive-definite inertia"});
    expectError(withBall(R"(, "inertia": 1)"), {"bodies[1].inertia: expected [Ixx, Iyy, Izz] or a 3x3 matrix"});
}

}  // namespace
}  // namespace vroc
