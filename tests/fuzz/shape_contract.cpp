// SPDX-License-Identifier: MIT
#include "shape_contract.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include <Eigen/Eigenvalues>

#include "fuzz_require.h"

namespace vroc::fuzz {

namespace {

bool finite(const Vec3& v) { return v.allFinite(); }

}  // namespace

void checkPolyhedron(const ConvexPolyhedron& hull, double max_abs) {
    const int v_count = static_cast<int>(hull.vertices.size());
    const std::size_t f_count = hull.faces.size();
    VROC_FUZZ_REQUIRE(v_count >= 4 && f_count >= 4);
    VROC_FUZZ_REQUIRE(hull.face_normals.size() == f_count && hull.face_offsets.size() == f_count);
    Vec3 lo = hull.vertices[0], hi = hull.vertices[0];
    for (const Vec3& v : hull.vertices) {
        VROC_FUZZ_REQUIRE(finite(v) && v.cwiseAbs().maxCoeff() <= max_abs);
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
    }
    const double diagonal = (hi - lo).norm();
    VROC_FUZZ_REQUIRE(diagonal > 0);
    // 1e-8 L is the documented tolerance; the 1.01 and the absolute term leave room for this
    // check's own rounding of n.v - d, about 1e-16 of the coordinates' magnitude.
    const double tolerance = 1.01e-8 * diagonal + 4e-16 * std::max(hi.cwiseAbs().maxCoeff(), lo.cwiseAbs().maxCoeff());

    std::map<std::pair<int, int>, int> directed;   // edge -> times used
    for (std::size_t f = 0; f < f_count; ++f) {
        const std::vector<int>& face = hull.faces[f];
        VROC_FUZZ_REQUIRE(face.size() >= 3);
        const Vec3& n = hull.face_normals[f];
        const double d = hull.face_offsets[f];
        VROC_FUZZ_REQUIRE(finite(n) && std::isfinite(d) && std::abs(n.norm() - 1) <= 1e-9);
        for (std::size_t i = 0; i < face.size(); ++i) {
            const int a = face[i], b = face[(i + 1) % face.size()];
            VROC_FUZZ_REQUIRE(a >= 0 && a < v_count && b >= 0 && b < v_count && a != b);
            VROC_FUZZ_REQUIRE(std::abs(n.dot(hull.vertices[a]) - d) <= tolerance);   // planar
            ++directed[{a, b}];
        }
        // Every vertex behind the plane: convex, and (the hull having volume) the normal points out.
        for (const Vec3& v : hull.vertices) VROC_FUZZ_REQUIRE(n.dot(v) - d <= tolerance);
    }
    for (const auto& [edge, count] : directed) {
        VROC_FUZZ_REQUIRE(count == 1);   // consistently oriented
        const auto reverse = directed.find({edge.second, edge.first});
        VROC_FUZZ_REQUIRE(reverse != directed.end() && reverse->second == 1);   // closed
    }
    const long edges = static_cast<long>(directed.size()) / 2;
    VROC_FUZZ_REQUIRE(v_count - edges + static_cast<long>(f_count) == 2);   // Euler, genus 0
}

void checkPose(const Pose& pose, double max_abs) {
    VROC_FUZZ_REQUIRE(finite(pose.position) && pose.position.cwiseAbs().maxCoeff() <= max_abs);
    VROC_FUZZ_REQUIRE(pose.orientation.coeffs().allFinite());
    VROC_FUZZ_REQUIRE(std::abs(pose.orientation.norm() - 1) <= 1e-12);
}

void checkShape(const Shape& shape) {
    constexpr double kMinSize = 1e-6, kMaxSize = 1e6, kMaxCoordinate = 1e6;   // scene_limits.h
    switch (shape.kind) {
    case Shape::Kind::Sphere:
        VROC_FUZZ_REQUIRE(shape.radius >= kMinSize && shape.radius <= kMaxSize);
        break;
    case Shape::Kind::Box:
        VROC_FUZZ_REQUIRE(shape.half_extents.minCoeff() >= kMinSize && shape.half_extents.maxCoeff() <= kMaxSize);
        break;
    case Shape::Kind::Hull:
        VROC_FUZZ_REQUIRE(shape.hull != nullptr);
        checkPolyhedron(*shape.hull, kMaxCoordinate);
        break;
    case Shape::Kind::Compound:
        VROC_FUZZ_REQUIRE(!shape.parts.empty());
        for (const ShapePart& part : shape.parts) {
            VROC_FUZZ_REQUIRE(part.shape.kind != Shape::Kind::Compound);   // flattened
            // Part positions compose (nested compounds): each is within a few times the range.
            VROC_FUZZ_REQUIRE(part.pose.position.allFinite());
            VROC_FUZZ_REQUIRE(std::abs(part.pose.orientation.norm() - 1) <= 1e-12);
            checkShape(part.shape);
        }
        break;
    }
    VROC_FUZZ_REQUIRE(std::isfinite(shape.boundingRadius()) && shape.boundingRadius() > 0);
}

void checkMassProperties(const MassProperties& p, double mass) {
    VROC_FUZZ_REQUIRE(std::abs(p.mass - mass) <= 1e-12 * mass);
    VROC_FUZZ_REQUIRE(std::isfinite(p.volume) && p.volume > 0);
    VROC_FUZZ_REQUIRE(finite(p.center_of_mass));
    VROC_FUZZ_REQUIRE(p.inertia.allFinite());
    const double largest = p.inertia.cwiseAbs().maxCoeff();
    VROC_FUZZ_REQUIRE(largest > 0);
    VROC_FUZZ_REQUIRE((p.inertia - p.inertia.transpose()).cwiseAbs().maxCoeff() <= 1e-9 * largest);
    const Vec3 m = Eigen::SelfAdjointEigenSolver<Mat3>(p.inertia, Eigen::EigenvaluesOnly).eigenvalues();
    const double rounding = 1e-12 * largest;
    VROC_FUZZ_REQUIRE(m.x() > -rounding);
    VROC_FUZZ_REQUIRE(m.z() <= m.x() + m.y() + rounding + 1e-9 * m.z());
}

}  // namespace vroc::fuzz
