// SPDX-License-Identifier: MIT
// Loader round trips: every key and shape kind lands in the Scene as written, and every scene in
// scenes/ loads with the facts its description states. Expected values are the literals written
// in the JSON, closed forms (inertia of a sphere/box, volume of a tetrahedron), or SHA-256 test
// vectors (FIPS 180-2).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "../../core/src/did_you_mean.h"
#include "../../core/src/sha256.h"
#include "vroc/core/errors.h"
#include "vroc/core/mass_properties.h"
#include "vroc/core/scene_loader.h"

namespace vroc {
namespace {

const std::string kDataDir = std::string(VROC_SOURCE_DIR) + "/tests/data/scenes";
const std::string kScenesDir = std::string(VROC_SOURCE_DIR) + "/scenes";
const std::string kOrigin = kDataDir + "/inline.json";   // anchors relative mesh paths

std::string sceneWith(const std::string& bodies, const std::string& top = "") {
    return R"({"format": "vroc-scene/1", "name": "t", )" + top +
           R"("materials": {"rubber": {"restitution": 0.25, "friction": 0.75}, "steel": {"restitution": 0.5, "friction": 0.125}},
              "bodies": [)" + bodies + "]}";
}

Scene loadBodies(const std::string& bodies, const std::string& top = "") {
    return loadSceneFromString(sceneWith(bodies, top), kOrigin);
}

std::string meshBody(const std::string& mesh_json) {
    return R"({"name": "m", "role": "real", "material": "steel", "position": [0, 0, 0], "shape": {"mesh": )" +
           mesh_json + "}}";
}

bool hasVertex(const ConvexPolyhedron& hull, const Vec3& v) {
    for (const Vec3& p : hull.vertices)
        if ((p - v).norm() < 1e-12) return true;
    return false;
}

// Volume of a convex polyhedron from its faces (fan triangulation, divergence theorem): an
// answer independent of mass_properties.cpp.
double volumeOf(const ConvexPolyhedron& hull) {
    double six_v = 0;
    for (const auto& f : hull.faces)
        for (std::size_t i = 1; i + 1 < f.size(); ++i)
            six_v += hull.vertices[f[0]].dot(hull.vertices[f[i]].cross(hull.vertices[f[i + 1]]));
    return six_v / 6;
}

TEST(SceneLoader, TopLevelKeysLandAsWritten) {
    const Scene s = loadSceneFromString(
        R"({"format": "vroc-scene/1", "name": "top", "description": "d e s c",
            "gravity": [0.5, -1.25, -3.0], "frame_dt": 0.002, "collision_distance": 0.0025,
            "materials": {"rubber": {"restitution": 0.25, "friction": 0.75}, "ice": {"restitution": 1, "friction": 0}},
            "bodies": [{"name": "b", "role": "virtual", "material": "ice", "mass": 2, "position": [1, 2, 3],
                        "shape": {"sphere": {"radius": 0.5}}}]})",
        kOrigin);
    EXPECT_EQ(s.name, "top");
    EXPECT_EQ(s.description, "d e s c");
    EXPECT_EQ(s.gravity, Vec3(0.5, -1.25, -3.0));
    EXPECT_EQ(s.frame_dt, 0.002);
    EXPECT_EQ(s.collision_distance, 0.0025);
    ASSERT_EQ(s.materials.size(), 2u);   // file order, not alphabetical
    EXPECT_EQ(s.materials[0].name, "rubber");
    EXPECT_EQ(s.materials[0].restitution, 0.25);
    EXPECT_EQ(s.materials[0].friction, 0.75);
    EXPECT_EQ(s.materials[1].name, "ice");
    EXPECT_EQ(s.materials[1].restitution, 1.0);
    EXPECT_EQ(s.materials[1].friction, 0.0);
    ASSERT_EQ(s.bodies.size(), 1u);
    EXPECT_EQ(s.bodies[0].material, 1);
    EXPECT_EQ(s.source_path, "");   // loaded from a string
}

TEST(SceneLoader, DefaultsWhenOptionalKeysAreAbsent) {
    const Scene s = loadBodies(R"({"name": "b", "role": "virtual", "material": "rubber", "mass": 1,
                                   "position": [0, 0, 0], "shape": {"sphere": {"radius": 1}}})");
    EXPECT_EQ(s.description, "");
    EXPECT_EQ(s.gravity, Vec3(0, 0, -9.81));
    EXPECT_EQ(s.frame_dt, 1.0 / 60.0);
    EXPECT_EQ(s.collision_distance, 1e-3);
    const Body& b = s.bodies[0];
    EXPECT_EQ(b.pose.orientation.coeffs(), Quat::Identity().coeffs());
    EXPECT_EQ(b.linear_velocity, Vec3::Zero());
    EXPECT_EQ(b.angular_velocity, Vec3::Zero());
}

TEST(SceneLoader, VirtualBodyFieldsLandAsWritten) {
    const Scene s = loadBodies(R"({"name": "ball", "role": "virtual", "material": "steel", "mass": 3.5,
        "position": [0.25, -0.5, 2], "linear_velocity": [1, -2, 3], "angular_velocity": [-4, 5, 0.5],
        "shape": {"sphere": {"radius": 0.2}}})");
    const Body& b = s.bodies[0];
    EXPECT_EQ(b.name, "ball");
    EXPECT_EQ(b.role, BodyRole::Virtual);
    EXPECT_FALSE(b.isStatic());
    EXPECT_EQ(b.material, 1);
    EXPECT_EQ(b.pose.position, Vec3(0.25, -0.5, 2));
    EXPECT_EQ(b.linear_velocity, Vec3(1, -2, 3));
    EXPECT_EQ(b.angular_velocity, Vec3(-4, 5, 0.5));
    ASSERT_EQ(b.shape.kind, Shape::Kind::Sphere);
    EXPECT_EQ(b.shape.radius, 0.2);
    EXPECT_DOUBLE_EQ(b.mass_properties.mass, 3.5);
    // Solid sphere: I = 2/5 m r^2 about every axis through the centre.
    const double i = 0.4 * 3.5 * 0.2 * 0.2;
    EXPECT_TRUE(b.mass_properties.inertia.isApprox(Mat3::Identity() * i, 1e-12)) << b.mass_properties.inertia;
    EXPECT_LT(b.mass_properties.center_of_mass.norm(), 1e-15);
}

TEST(SceneLoader, RealBodyIsStaticWithZeroMass) {
    const Scene s = loadBodies(R"({"name": "floor", "role": "real", "material": "steel",
        "position": [0, 0, -0.5], "shape": {"box": {"half_extents": [2, 3, 0.5]}}})");
    const Body& b = s.bodies[0];
    EXPECT_EQ(b.role, BodyRole::Real);
    EXPECT_TRUE(b.isStatic());
    EXPECT_EQ(b.mass_properties.mass, 0.0);
    EXPECT_EQ(b.mass_properties.inertia, Mat3::Zero());
    ASSERT_EQ(b.shape.kind, Shape::Kind::Box);
    EXPECT_EQ(b.shape.half_extents, Vec3(2, 3, 0.5));
    EXPECT_EQ(s.virtualBodyCount(), 0u);
}

TEST(SceneLoader, TrackedBodyMovesWithInfiniteMassAndNamesItsDevice) {
    const Scene s = loadBodies(R"({"name": "pad", "role": "tracked", "material": "steel",
        "position": [0, 0, 1], "linear_velocity": [1, 0, 0], "angular_velocity": [0, 0, 2],
        "shape": {"box": {"half_extents": [0.1, 0.2, 0.01]}},
        "tracking": {"device": "udp:port=4242", "sensor": 3}})");
    const Body& b = s.bodies[0];
    EXPECT_EQ(b.role, BodyRole::Tracked);
    EXPECT_TRUE(b.isTracked());
    EXPECT_FALSE(b.isStatic());
    EXPECT_FALSE(b.isDynamic());
    EXPECT_EQ(b.mass_properties.mass, 0.0);
    EXPECT_EQ(b.linear_velocity, Vec3(1, 0, 0));
    EXPECT_EQ(b.angular_velocity, Vec3(0, 0, 2));
    EXPECT_EQ(b.tracking.device, "udp:port=4242");
    EXPECT_EQ(b.tracking.sensor, 3);
    EXPECT_EQ(s.virtualBodyCount(), 0u);
    // Without `tracking`: no device, sensor 0 (it moves at its file velocities).
    const Scene t = loadBodies(R"({"name": "pad", "role": "tracked", "material": "steel",
        "position": [0, 0, 1], "shape": {"sphere": {"radius": 0.1}}})");
    EXPECT_TRUE(t.bodies[0].tracking.device.empty());
    EXPECT_EQ(t.bodies[0].tracking.sensor, 0);
}

TEST(SceneLoader, BoxInertiaIsTheClosedForm) {
    const Scene s = loadBodies(R"({"name": "b", "role": "virtual", "material": "steel", "mass": 6,
        "position": [0, 0, 0], "shape": {"box": {"half_extents": [0.5, 1, 1.5]}}})");
    // Solid box with full sides a, b, c: Ixx = m (b^2 + c^2) / 12, ...
    const double m = 6, a = 1, b = 2, c = 3;
    const Vec3 expected(m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12);
    EXPECT_TRUE(s.bodies[0].mass_properties.inertia.isApprox(Mat3(expected.asDiagonal()), 1e-12));
}

TEST(SceneLoader, QuaternionIsReadXYZWAndNormalised) {
    const double half = 0.3;   // rotation by 0.6 rad about z
    std::ostringstream body;
    body.precision(17);
    body << R"({"name": "q", "role": "real", "material": "steel", "position": [0, 0, 0],
               "shape": {"sphere": {"radius": 1}}, "orientation": [0, 0, )" << std::sin(half) << ", " << std::cos(half) << "]}";
    const Quat q = loadBodies(body.str()).bodies[0].pose.orientation;
    const Vec3 x = q * Vec3::UnitX();
    EXPECT_NEAR(x.x(), std::cos(0.6), 1e-15);
    EXPECT_NEAR(x.y(), std::sin(0.6), 1e-15);
    EXPECT_NEAR(x.z(), 0.0, 1e-15);
    // [x, y, z, w] = [0, 3, 0, 4] is 5 x the unit quaternion (0, 0.6, 0, 0.8).
    const Quat n = loadBodies(R"({"name": "q", "role": "real", "material": "steel", "position": [0, 0, 0],
        "shape": {"sphere": {"radius": 1}}, "orientation": [0, 3, 0, 4]})").bodies[0].pose.orientation;
    EXPECT_DOUBLE_EQ(n.w(), 0.8);
    EXPECT_DOUBLE_EQ(n.x(), 0.0);
    EXPECT_DOUBLE_EQ(n.y(), 0.6);
    EXPECT_DOUBLE_EQ(n.z(), 0.0);
    // Components near the top of the double range normalise too (their squares overflow): the
    // same rotation as [0, 1, 0, 0] and as [1, 1, 1, 1] / 2, never the zero quaternion.
    auto load = [&](const std::string& q) {
        return loadBodies(R"({"name": "q", "role": "real", "material": "steel", "position": [0, 0, 0],
            "shape": {"sphere": {"radius": 1}}, "orientation": )" + q + "}").bodies[0].pose.orientation;
    };
    const Quat big = load("[0, 1e308, 0, 1]");
    EXPECT_DOUBLE_EQ(big.y(), 1.0);
    EXPECT_NEAR(big.w(), 0.0, 1e-300);
    EXPECT_DOUBLE_EQ(big.x(), 0.0);
    const Quat all = load("[1.5e308, 1.5e308, 1.5e308, 1.5e308]");
    for (double c : {all.x(), all.y(), all.z(), all.w()}) EXPECT_DOUBLE_EQ(c, 0.5);
}

TEST(SceneLoader, InertiaOverrideDiagonalAndMatrix) {
    const std::string head = R"({"name": "b", "role": "virtual", "material": "steel", "mass": 1,
        "position": [0, 0, 0], "shape": {"sphere": {"radius": 1}}, "inertia": )";
    const Scene d = loadBodies(head + "[1, 2, 2.5]}");
    EXPECT_EQ(d.bodies[0].mass_properties.inertia, Mat3(Vec3(1, 2, 2.5).asDiagonal()));
    EXPECT_DOUBLE_EQ(d.bodies[0].mass_properties.mass, 1.0);   // mass is kept
    const Scene m = loadBodies(head + "[[2, 0.5, 0], [0.5, 2, 0.1], [0, 0.1, 3]]}");
    Mat3 expected;
    expected << 2, 0.5, 0, 0.5, 2, 0.1, 0, 0.1, 3;
    EXPECT_EQ(m.bodies[0].mass_properties.inertia, expected);
}

TEST(SceneLoader, HullShapeIsTheConvexHullOfThePoints) {
    // Unit corner tetrahedron plus an interior point that must not become a vertex.
    const Scene s = loadBodies(R"({"name": "h", "role": "virtual", "material": "steel", "mass": 1, "position": [0, 0, 0],
        "shape": {"hull": {"points": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [0.1, 0.1, 0.1]]}}})");
    const Shape& shape = s.bodies[0].shape;
    ASSERT_EQ(shape.kind, Shape::Kind::Hull);
    ASSERT_EQ(shape.hull->vertices.size(), 4u);
    EXPECT_FALSE(hasVertex(*shape.hull, Vec3(0.1, 0.1, 0.1)));
    EXPECT_NEAR(volumeOf(*shape.hull), 1.0 / 6.0, 1e-15);
    // Centroid of a tetrahedron: mean of its vertices.
    EXPECT_TRUE(s.bodies[0].mass_properties.center_of_mass.isApprox(Vec3::Constant(0.25), 1e-12));
}

TEST(SceneLoader, MeshHullWithVectorAndScalarScale) {
    const Scene s = loadBodies(meshBody(R"({"file": "tetra.obj", "scale": [2, 3, 4], "mode": "hull"})"));
    const Shape& shape = s.bodies[0].shape;
    ASSERT_EQ(shape.kind, Shape::Kind::Hull);
    ASSERT_EQ(shape.hull->vertices.size(), 4u);
    for (const Vec3& v : {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 3, 0), Vec3(0, 0, 4)})
        EXPECT_TRUE(hasVertex(*shape.hull, v)) << v.transpose();
    const Scene t = loadBodies(meshBody(R"({"file": "tetra.obj", "scale": 0.5})"));   // mode defaults to hull
    ASSERT_EQ(t.bodies[0].shape.kind, Shape::Kind::Hull);
    EXPECT_NEAR(volumeOf(*t.bodies[0].shape.hull), 0.125 / 6.0, 1e-15);
}

TEST(SceneLoader, MeshFormatsObjStlPlyGltfGiveTheSameHull) {
    for (const char* file : {"tetra.obj", "tetra.stl", "tetra.ply", "tetra.gltf"}) {
        SCOPED_TRACE(file);
        const Scene s = loadBodies(meshBody(std::string(R"({"file": ")") + file + R"("})"));
        const Shape& shape = s.bodies[0].shape;
        ASSERT_EQ(shape.kind, Shape::Kind::Hull);
        ASSERT_EQ(shape.hull->vertices.size(), 4u);
        for (const Vec3& v : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)})
            EXPECT_TRUE(hasVertex(*shape.hull, v)) << v.transpose();
    }
}

TEST(SceneLoader, MeshPartsGiveOneConvexPartPerMesh) {
    const Scene s = loadBodies(meshBody(R"({"file": "two_cubes.obj", "mode": "parts", "scale": 2})"));
    const Shape& shape = s.bodies[0].shape;
    ASSERT_EQ(shape.kind, Shape::Kind::Compound);
    ASSERT_EQ(shape.parts.size(), 2u);
    for (const ShapePart& part : shape.parts) {
        ASSERT_EQ(part.shape.kind, Shape::Kind::Hull);
        EXPECT_EQ(part.shape.hull->vertices.size(), 8u);
        EXPECT_NEAR(volumeOf(*part.shape.hull), 8.0, 1e-12);   // unit cube scaled by 2
        EXPECT_EQ(part.pose.position, Vec3::Zero());
    }
    // 'left' spans x in [0, 2] after scaling, 'right' x in [6, 8].
    EXPECT_TRUE(hasVertex(*shape.parts[0].shape.hull, Vec3(0, 0, 0)));
    EXPECT_TRUE(hasVertex(*shape.parts[1].shape.hull, Vec3(8, 2, 2)));
    // The same file as one hull covers both cubes.
    const Scene h = loadBodies(meshBody(R"({"file": "two_cubes.obj", "mode": "hull"})"));
    EXPECT_NEAR(volumeOf(*h.bodies[0].shape.hull), 4.0, 1e-12);
}

TEST(SceneLoader, CompoundPartsWithPosesAndFlattening) {
    const Scene s = loadBodies(R"({"name": "c", "role": "real", "material": "steel", "position": [0, 0, 0],
        "shape": {"compound": {"parts": [
            {"shape": {"sphere": {"radius": 0.5}}, "position": [1, 0, 0]},
            {"shape": {"box": {"half_extents": [1, 1, 1]}}, "orientation": [0, 0, 1, 0]},
            {"shape": {"mesh": {"file": "two_cubes.obj", "mode": "parts"}}, "position": [0, 0, 10]},
            {"shape": {"compound": {"parts": [{"shape": {"sphere": {"radius": 0.25}}, "position": [0, 2, 0]}]}},
             "position": [0, 0, -1], "orientation": [0, 0, 0.7071067811865476, 0.7071067811865476]}
        ]}}})");
    const Shape& shape = s.bodies[0].shape;
    ASSERT_EQ(shape.kind, Shape::Kind::Compound);
    ASSERT_EQ(shape.parts.size(), 5u);   // sphere, box, 2 mesh parts, 1 flattened nested part
    EXPECT_EQ(shape.parts[0].shape.kind, Shape::Kind::Sphere);
    EXPECT_EQ(shape.parts[0].pose.position, Vec3(1, 0, 0));
    EXPECT_EQ(shape.parts[1].shape.kind, Shape::Kind::Box);
    EXPECT_NEAR(std::abs(shape.parts[1].pose.orientation.z()), 1.0, 1e-15);
    EXPECT_EQ(shape.parts[2].shape.kind, Shape::Kind::Hull);
    EXPECT_EQ(shape.parts[3].shape.kind, Shape::Kind::Hull);
    EXPECT_EQ(shape.parts[2].pose.position, Vec3(0, 0, 10));
    // Nested part at (0, 2, 0), rotated 90 deg about z -> (-2, 0, 0), then moved by (0, 0, -1).
    EXPECT_EQ(shape.parts[4].shape.kind, Shape::Kind::Sphere);
    EXPECT_TRUE(shape.parts[4].pose.position.isApprox(Vec3(-2, 0, -1), 1e-15)) << shape.parts[4].pose.position.transpose();
}

TEST(SceneLoader, Sha256OfFileBytesAndSourcePath) {
    // FIPS 180-2 test vectors: the helper is right...
    EXPECT_EQ(sha256Hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    EXPECT_EQ(sha256Hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
    // ...and the loader applies it to the exact bytes of the file.
    const std::string path = kScenesDir + "/ball_drop.json";
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const Scene s = loadScene(path);
    EXPECT_EQ(s.source_sha256, sha256Hex(bytes));
    EXPECT_EQ(s.source_path, path);
    // One more space changes the hash.
    EXPECT_NE(loadSceneFromString(bytes + " ", path).source_sha256, s.source_sha256);
}

TEST(SceneLoader, DidYouMeanDistance) {
    EXPECT_EQ(editDistance("restitution", "restitution"), 0);
    EXPECT_EQ(editDistance("restituion", "restitution"), 1);    // deletion
    EXPECT_EQ(editDistance("fritcion", "friction"), 1);         // transposition
    EXPECT_EQ(editDistance("mass", "name"), 3);
    EXPECT_EQ(editDistance("", "abc"), 3);
    const std::vector<std::string> keys = {"restitution", "friction"};
    EXPECT_EQ(nearestWord("frction", keys), "friction");
}

TEST(SceneLoader, DocumentationExampleLoads) {
    // The JSON block under "## Example" in docs/scene-format.md, loaded as if it were in scenes/.
    std::ifstream in(std::string(VROC_SOURCE_DIR) + "/docs/scene-format.md");
    const std::string doc((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::size_t section = doc.find("## Example");
    ASSERT_NE(section, std::string::npos);
    const std::size_t begin = doc.find("```json\n", section);
    ASSERT_NE(begin, std::string::npos);
    const std::size_t end = doc.find("```", begin + 8);
    ASSERT_NE(end, std::string::npos);
    const Scene s = loadSceneFromString(doc.substr(begin + 8, end - begin - 8), kScenesDir + "/example.json");
    EXPECT_EQ(s.name, "example");
    ASSERT_EQ(s.bodies.size(), 4u);
    EXPECT_EQ(s.bodies[1].shape.parts.size(), 6u);   // the chair mesh in parts mode
    EXPECT_EQ(s.bodies[3].shape.parts.size(), 3u);
    EXPECT_EQ(s.bodies[3].mass_properties.inertia, Mat3(Vec3(0.001, 0.02, 0.02).asDiagonal()));
}

// ---- the committed scenes -------------------------------------------------------------------

Scene loadCommitted(const std::string& name) { return loadScene(kScenesDir + "/" + name); }

TEST(CommittedScenes, EverySceneLoads) {
    int count = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(kScenesDir)) {
        if (entry.path().extension() != ".json") continue;
        SCOPED_TRACE(entry.path().string());
        EXPECT_NO_THROW({
            const Scene s = loadScene(entry.path().string());
            EXPECT_EQ(s.name, entry.path().stem().string());   // file name == scene name
            EXPECT_GE(s.virtualBodyCount(), 1u);
            // z is up in every scene: gravity is standard along -z, or off (zero-g scenes).
            EXPECT_TRUE(s.gravity == Vec3(0, 0, -9.81) || s.gravity == Vec3::Zero()) << s.gravity.transpose();
        });
        ++count;
    }
    EXPECT_GE(count, 7);
}

TEST(CommittedScenes, BallDropMatchesItsDescription) {
    for (const auto& [file, e] : {std::pair{"ball_drop.json", 0.5}, std::pair{"ball_drop_e1.json", 1.0}}) {
        const Scene s = loadCommitted(file);
        const Body& ball = s.bodies[s.findBody("ball")];
        const Body& floor = s.bodies[s.findBody("floor")];
        EXPECT_EQ(ball.shape.radius, 0.1);
        // h = 1 m between the ball's lowest point and the floor's top face.
        const double floor_top = floor.pose.position.z() + floor.shape.half_extents.z();
        EXPECT_DOUBLE_EQ(ball.pose.position.z() - ball.shape.radius - floor_top, 1.0);
        EXPECT_EQ(combineMaterials(s.materials[ball.material], s.materials[floor.material]).restitution, e);
        EXPECT_EQ(s.frame_dt, 1.0 / 60.0);
        EXPECT_EQ(s.collision_distance, 1e-3);
    }
}

TEST(CommittedScenes, StaircaseHasOneConvexPartPerStep) {
    const Scene s = loadCommitted("staircase.json");
    const Body& stairs = s.bodies[s.findBody("staircase")];
    ASSERT_EQ(stairs.shape.kind, Shape::Kind::Compound);
    ASSERT_EQ(stairs.shape.parts.size(), 6u);
    for (std::size_t i = 0; i < 6; ++i) {
        double top = -1;
        for (const Vec3& v : stairs.shape.parts[i].shape.hull->vertices) top = std::max(top, v.z());
        EXPECT_NEAR(top, (6 - static_cast<double>(i)) * 0.18, 1e-6) << "step " << i;
    }
    EXPECT_EQ(s.virtualBodyCount(), 5u);
}

TEST(CommittedScenes, ChairHasSeatBackAndFourLegs) {
    const Scene s = loadCommitted("chair.json");
    const Body& chair = s.bodies[s.findBody("chair")];
    ASSERT_EQ(chair.shape.kind, Shape::Kind::Compound);
    EXPECT_EQ(chair.shape.parts.size(), 6u);
    EXPECT_EQ(s.virtualBodyCount(), 3u);
}

TEST(CommittedScenes, DeskHasExactly100RealObjectsAndOneVirtual) {
    const Scene s = loadCommitted("desk.json");
    EXPECT_EQ(s.bodies.size() - s.virtualBodyCount(), 100u);
    EXPECT_EQ(s.virtualBodyCount(), 1u);
}

TEST(CommittedScenes, NotepadAndHullRest) {
    const Scene n = loadCommitted("notepad.json");
    EXPECT_EQ(n.bodies[n.findBody("table")].shape.kind, Shape::Kind::Compound);
    EXPECT_EQ(n.bodies[n.findBody("notepad")].shape.kind, Shape::Kind::Box);
    const Scene h = loadCommitted("hull_rest.json");
    const Body& gem = h.bodies[h.findBody("gem")];
    ASSERT_EQ(gem.shape.kind, Shape::Kind::Hull);
    // Its description: lowest vertex 0.30 m above the floor at the start.
    double lowest = 1e9;
    for (const Vec3& v : gem.shape.hull->vertices) lowest = std::min(lowest, gem.pose.apply(v).z());
    EXPECT_NEAR(lowest, 0.30, 1e-3);
}

}  // namespace
}  // namespace vroc
