// SPDX-License-Identifier: MIT
// Shapes of `vroc-scene/1` (docs/scene-format.md, "Shapes").
#include <string>
#include <vector>

#include <Eigen/Eigenvalues>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "mesh_import.h"
#include "scene_limits.h"
#include "scene_loader_internal.h"
#include "vroc/core/errors.h"

namespace vroc {

namespace {

// Hull through qhull; degenerate input becomes an InputError at `where`.
ConvexPolyhedron hullOf(const std::vector<Vec3>& points, const JsonReader& where, std::string_view what) {
    try {
        return ConvexPolyhedron::fromPoints(points);
    } catch (const GeometryError& e) {
        where.fail(fmt::format("degenerate {}: {} (expected at least 4 points not all in one plane)", what,
                               e.what()));
    }
}

Shape readSphere(const JsonReader& r) {
    r.requireObject({"radius"});
    return Shape::sphere(r.at("radius").positiveIn(scene_limits::kMinSize, scene_limits::kMaxSize, " [m]"));
}

Shape readBox(const JsonReader& r) {
    r.requireObject({"half_extents"});
    const JsonReader he = r.at("half_extents");
    he.vec3();   // shape and type first, then each component's range
    auto extent = [&](std::size_t i) {
        return he.element(i).positiveIn(scene_limits::kMinSize, scene_limits::kMaxSize, " [m]");
    };
    return Shape::box(Vec3(extent(0), extent(1), extent(2)));
}

Shape readHull(const JsonReader& r) {
    r.requireObject({"points"});
    const JsonReader pts = r.at("points");
    std::vector<Vec3> points;
    for (std::size_t i = 0; i < pts.arraySize(); ++i)
        points.push_back(pts.element(i).vec3Within(scene_limits::kMaxCoordinate, " [m]"));
    return Shape::convexHull(hullOf(points, pts, fmt::format("hull of {} points", points.size())));
}

Vec3 readScale(const std::optional<JsonReader>& r) {
    if (!r) return Vec3::Ones();
    auto factor = [](const JsonReader& f) { return f.positiveIn(scene_limits::kMinScale, scene_limits::kMaxScale, ""); };
    if (r->isNumber()) return Vec3::Constant(factor(*r));
    if (!r->isArray() || r->arraySize() != 3)
        r->fail(fmt::format("expected a number or [sx, sy, sz], got {}", r->describe()));
    return Vec3(factor(r->element(0)), factor(r->element(1)), factor(r->element(2)));
}

Shape readMesh(const JsonReader& r, const std::filesystem::path& base_dir) {
    r.requireObject({"file", "scale", "mode"});
    const JsonReader file = r.at("file");
    const std::string path = (base_dir / file.string()).lexically_normal().string();
    const Vec3 scale = readScale(r.find("scale"));
    std::string mode = "hull";
    if (auto m = r.find("mode")) {
        mode = m->string();
        if (mode != "hull" && mode != "parts")
            m->fail(fmt::format("expected \"hull\" or \"parts\", got \"{}\"", mode));
    }
    const std::vector<MeshPoints> meshes = importMeshPoints(path, scale, file.origin() + ": " + file.path());
    for (const MeshPoints& m : meshes)
        for (const Vec3& v : m.vertices)
            if (!(v.cwiseAbs().maxCoeff() <= scene_limits::kMaxCoordinate))
                file.fail(fmt::format("mesh '{}' scaled by ({}, {}, {}) has a vertex at ({}, {}, {}) m, outside the "
                                      "accepted range of +-{} m per coordinate (docs/scene-format.md)",
                                      path, scale.x(), scale.y(), scale.z(), v.x(), v.y(), v.z(),
                                      scene_limits::kMaxCoordinate));
    if (mode == "hull") {
        std::vector<Vec3> all;
        for (const MeshPoints& m : meshes) all.insert(all.end(), m.vertices.begin(), m.vertices.end());
        return Shape::convexHull(hullOf(all, file, fmt::format("hull of mesh '{}'", path)));
    }
    std::vector<ShapePart> parts;
    for (std::size_t i = 0; i < meshes.size(); ++i) {
        const std::string what = fmt::format("part {} ('{}') of mesh '{}'", i, meshes[i].name, path);
        parts.push_back({Shape::convexHull(hullOf(meshes[i].vertices, file, what)), Pose::identity()});
    }
    return Shape::compound(std::move(parts));
}

Pose readPartPose(const JsonReader& part) {
    Pose pose;
    if (auto p = part.find("position")) pose.position = p->vec3Within(scene_limits::kMaxCoordinate, " [m]");
    if (auto q = part.find("orientation")) pose.orientation = q->quaternion();
    return pose;
}

Shape readCompound(const JsonReader& r, const std::filesystem::path& base_dir) {
    r.requireObject({"parts"});
    const JsonReader list = r.at("parts");
    if (list.arraySize() == 0) list.fail("expected at least one part");
    std::vector<ShapePart> parts;
    for (std::size_t i = 0; i < list.arraySize(); ++i) {
        const JsonReader part = list.element(i);
        part.requireObject({"shape", "position", "orientation"});
        const Pose pose = readPartPose(part);
        Shape shape = readShape(part.at("shape"), base_dir);
        if (shape.kind != Shape::Kind::Compound) {
            parts.push_back({std::move(shape), pose});
            continue;
        }
        // Flatten: a nested compound (or a mesh in "parts" mode) contributes its own parts.
        for (ShapePart& sub : shape.parts) parts.push_back({std::move(sub.shape), pose * sub.pose});
    }
    return Shape::compound(std::move(parts));
}

}  // namespace

Shape readShape(const JsonReader& r, const std::filesystem::path& base_dir) {
    r.requireObject({"sphere", "box", "hull", "mesh", "compound"});
    const std::vector<std::string> kinds = r.keys();
    if (kinds.size() != 1)
        r.fail(fmt::format("expected exactly one of sphere, box, hull, mesh, compound; got {}",
                           kinds.empty() ? std::string("none") : fmt::format("`{}`", fmt::join(kinds, "`, `"))));
    const JsonReader body = r.at(kinds[0]);
    if (kinds[0] == "sphere") return readSphere(body);
    if (kinds[0] == "box") return readBox(body);
    if (kinds[0] == "hull") return readHull(body);
    if (kinds[0] == "mesh") return readMesh(body, base_dir);
    return readCompound(body, base_dir);
}

Mat3 readInertia(const JsonReader& r) {
    const std::string expected = "expected [Ixx, Iyy, Izz] or a 3x3 matrix [[..], [..], [..]] [kg m^2]";
    if (!r.isArray() || r.arraySize() != 3) r.fail(fmt::format("{}, got {}", expected, r.describe()));
    Mat3 inertia = Mat3::Zero();
    if (r.element(0).isNumber()) {
        for (int i = 0; i < 3; ++i)
            inertia(i, i) = r.element(i).positiveIn(scene_limits::kMinMoment, scene_limits::kMaxMoment, " [kg m^2]");
    } else {
        for (int i = 0; i < 3; ++i) {
            const JsonReader row = r.element(i);
            if (!row.isArray() || row.arraySize() != 3) row.fail(fmt::format("{}, got {}", expected, row.describe()));
            for (int j = 0; j < 3; ++j)
                inertia(i, j) = row.element(j).inRange(-scene_limits::kMaxMoment, scene_limits::kMaxMoment, " [kg m^2]");
        }
        const double scale = inertia.cwiseAbs().maxCoeff();
        if (!((inertia - inertia.transpose()).cwiseAbs().maxCoeff() <= 1e-9 * scale))
            r.fail("expected a symmetric matrix (|I_ij - I_ji| <= 1e-9 max|I|)");
        inertia = 0.5 * (inertia + inertia.transpose());
    }
    const Eigen::SelfAdjointEigenSolver<Mat3> eig(inertia);
    const Vec3 m = eig.eigenvalues();   // ascending
    if (!(m.x() > 0))
        r.fail(fmt::format("expected a positive-definite inertia, got principal moments {}, {}, {}", m.x(), m.y(), m.z()));
    if (!(m.z() <= (m.x() + m.y()) * (1 + 1e-9)))
        r.fail(fmt::format("principal moments {}, {}, {} break the triangle inequality I3 <= I1 + I2 "
                           "(no rigid body has them)", m.x(), m.y(), m.z()));
    return inertia;
}

}  // namespace vroc
