// SPDX-License-Identifier: MIT
// Fuzz target: mesh files through the scene loader's import path (core/src/mesh_import.h:
// assimp's ReadFile, node transforms, empty meshes dropped), then the convex hull and mass
// properties a `"mesh"` shape gets (docs/fuzzing.md). The first byte picks the file extension,
// which is how assimp chooses its importer: 0 OBJ, 1 STL, 2 PLY, 3 glTF, 4 GLB (modulo 5); the
// rest is the file.
// Contract: importMeshPoints throws InputError (one line, starting with the context it was given)
// or returns at least one part, each with at least one vertex. When every vertex is finite and in
// the accepted range, ConvexPolyhedron::fromPoints throws GeometryError or returns a hull that
// satisfies checkPolyhedron, whose vertices are input points and which contains every input point
// within 1e-8 of the bounding-box diagonal; its mass properties, unless GeometryError (no volume),
// satisfy checkMassProperties.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <vector>

#include "fuzz_require.h"
#include "mesh_import.h"
#include "scratch_file.h"
#include "shape_contract.h"
#include "vroc/core/errors.h"
#include "vroc/core/mass_properties.h"

namespace {

constexpr double kMaxCoordinate = 1e6;   // core/src/scene_limits.h
const std::string kContext = "fuzz.json: bodies[0].shape.mesh.file";

void checkHullOf(const std::vector<vroc::Vec3>& points) {
    using namespace vroc;
    ConvexPolyhedron hull;
    try {
        hull = ConvexPolyhedron::fromPoints(points);
    } catch (const GeometryError&) {
        return;   // degenerate input: the loader reports it as InputError
    }
    fuzz::checkPolyhedron(hull, kMaxCoordinate);
    std::vector<std::array<double, 3>> sorted;
    Vec3 lo = points[0], hi = points[0];
    for (const Vec3& p : points) {
        sorted.push_back({p.x(), p.y(), p.z()});
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    std::sort(sorted.begin(), sorted.end());
    for (const Vec3& v : hull.vertices)   // vertices are exact input points
        VROC_FUZZ_REQUIRE(std::binary_search(sorted.begin(), sorted.end(), std::array<double, 3>{v.x(), v.y(), v.z()}));
    const double tolerance = 1.01e-8 * (hi - lo).norm() + 4e-16 * std::max(hi.cwiseAbs().maxCoeff(), lo.cwiseAbs().maxCoeff());
    for (std::size_t f = 0; f < hull.faces.size(); ++f)
        for (const Vec3& p : points) VROC_FUZZ_REQUIRE(hull.face_normals[f].dot(p) - hull.face_offsets[f] <= tolerance);
    MassProperties props;
    try {
        props = massProperties(Shape::convexHull(std::move(hull)), 1.0);
    } catch (const GeometryError&) {
        return;
    }
    fuzz::checkMassProperties(props, 1.0);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace vroc;
    static const std::array<fuzz::ScratchFile, 5> files = {fuzz::ScratchFile("input.obj"), fuzz::ScratchFile("input.stl"),
                                                           fuzz::ScratchFile("input.ply"), fuzz::ScratchFile("input.gltf"),
                                                           fuzz::ScratchFile("input.glb")};
    if (size == 0) return 0;
    const fuzz::ScratchFile& file = files[data[0] % files.size()];
    file.write(data + 1, size - 1);
    std::vector<MeshPoints> parts;
    try {
        parts = importMeshPoints(file.path(), Vec3::Ones(), kContext);
    } catch (const InputError& e) {
        const std::string message = e.what();
        VROC_FUZZ_REQUIRE(message.rfind(kContext + ": ", 0) == 0);
        VROC_FUZZ_REQUIRE(message.find(file.path()) != std::string::npos);
        VROC_FUZZ_REQUIRE(message.find('\n') == std::string::npos);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "vroc fuzz: importMeshPoints threw a non-InputError: %s\n", e.what());
        VROC_FUZZ_REQUIRE(!"only InputError may leave importMeshPoints");
    }
    VROC_FUZZ_REQUIRE(!parts.empty());
    std::vector<Vec3> all;
    for (const MeshPoints& part : parts) {
        VROC_FUZZ_REQUIRE(!part.vertices.empty());
        all.insert(all.end(), part.vertices.begin(), part.vertices.end());
    }
    // The scene loader rejects a mesh with a vertex outside the range (or not finite) first.
    for (const Vec3& v : all)
        if (!(v.cwiseAbs().maxCoeff() <= kMaxCoordinate)) return 0;
    checkHullOf(all);
    return 0;
}
