// SPDX-License-Identifier: MIT
#include "polyhedron_checks.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <fmt/format.h>

namespace vroc::detail {
namespace {

using Edge = std::pair<int, int>;

std::string checkIndices(const ConvexPolyhedron& p) {
    const int nv = static_cast<int>(p.vertices.size());
    if (nv < 4 || p.faces.size() < 4) return fmt::format("{} vertices, {} faces (need >= 4 each)", nv, p.faces.size());
    if (p.face_normals.size() != p.faces.size() || p.face_offsets.size() != p.faces.size())
        return "face, normal and offset counts differ";
    for (size_t f = 0; f < p.faces.size(); ++f) {
        const auto& face = p.faces[f];
        if (face.size() < 3) return fmt::format("face {} has {} vertices", f, face.size());
        for (int v : face)
            if (v < 0 || v >= nv) return fmt::format("face {} has vertex index {} out of range", f, v);
    }
    return {};
}

/// Each directed edge must occur exactly once and its reverse exactly once.
std::string checkEdges(const ConvexPolyhedron& p, int& edge_count) {
    std::vector<Edge> directed;
    for (const auto& face : p.faces)
        for (size_t i = 0; i < face.size(); ++i) directed.emplace_back(face[i], face[(i + 1) % face.size()]);
    std::sort(directed.begin(), directed.end());
    if (std::adjacent_find(directed.begin(), directed.end()) != directed.end())
        return "a directed edge occurs twice (faces not consistently oriented)";
    for (const Edge& e : directed)
        if (!std::binary_search(directed.begin(), directed.end(), Edge{e.second, e.first}))
            return fmt::format("edge {}-{} has no opposite half-edge (surface not closed)", e.first, e.second);
    edge_count = static_cast<int>(directed.size() / 2);
    return {};
}

std::string checkPlanarity(const ConvexPolyhedron& p, double tol) {
    for (size_t f = 0; f < p.faces.size(); ++f) {
        const Vec3& n = p.face_normals[f];
        if (std::abs(n.norm() - 1.0) > 1e-9) return fmt::format("face {} normal is not unit", f);
        for (int v : p.faces[f]) {
            const double off = n.dot(p.vertices[v]) - p.face_offsets[f];
            if (std::abs(off) > tol) return fmt::format("face {} is not planar: vertex {} is {:.3g} m off its plane", f, v, off);
        }
    }
    return {};
}

std::string outsideMessage(int v, int f, double out) {
    return fmt::format("not convex: vertex {} is {:.3g} m outside face {}", v, out, f);
}

/// Every vertex against every face plane: O(V F).
std::string checkConvexityGlobal(const ConvexPolyhedron& p, double tol) {
    for (size_t f = 0; f < p.faces.size(); ++f)
        for (size_t v = 0; v < p.vertices.size(); ++v) {
            const double out = p.face_normals[f].dot(p.vertices[v]) - p.face_offsets[f];
            if (out > tol) return outsideMessage(static_cast<int>(v), static_cast<int>(f), out);
        }
    return {};
}

/// Every face against the vertices of its edge neighbours: O(E). On a closed, consistently
/// oriented surface of genus 0 local convexity implies global convexity.
std::string checkConvexityLocal(const ConvexPolyhedron& p, double tol) {
    std::vector<std::pair<Edge, int>> edge_face;   // directed edge -> face that owns it
    for (size_t f = 0; f < p.faces.size(); ++f) {
        const auto& face = p.faces[f];
        for (size_t i = 0; i < face.size(); ++i) edge_face.push_back({{face[i], face[(i + 1) % face.size()]}, static_cast<int>(f)});
    }
    std::sort(edge_face.begin(), edge_face.end());
    for (const auto& [edge, f] : edge_face) {
        auto it = std::lower_bound(edge_face.begin(), edge_face.end(), std::make_pair(Edge{edge.second, edge.first}, -1));
        for (int v : p.faces[it->second]) {
            const double out = p.face_normals[f].dot(p.vertices[v]) - p.face_offsets[f];
            if (out > tol) return outsideMessage(v, f, out);
        }
    }
    return {};
}

std::string checkVertexDegrees(const ConvexPolyhedron& p) {
    std::vector<int> degree(p.vertices.size(), 0);
    for (const auto& face : p.faces)
        for (int v : face) ++degree[v];
    for (size_t v = 0; v < degree.size(); ++v)
        if (degree[v] < 3) return fmt::format("vertex {} lies on only {} faces", v, degree[v]);
    return {};
}

}  // namespace

std::string checkPolyhedron(const ConvexPolyhedron& p, double tolerance, double global_budget) {
    if (std::string e = checkIndices(p); !e.empty()) return e;
    int edges = 0;
    if (std::string e = checkEdges(p, edges); !e.empty()) return e;
    const int euler = static_cast<int>(p.vertices.size()) - edges + static_cast<int>(p.faces.size());
    if (euler != 2) return fmt::format("Euler characteristic V - E + F = {} (expected 2)", euler);
    if (std::string e = checkVertexDegrees(p); !e.empty()) return e;
    if (std::string e = checkPlanarity(p, tolerance); !e.empty()) return e;
    // The all-pairs test is exact but quadratic; very large hulls use the local test.
    if (static_cast<double>(p.vertices.size()) * static_cast<double>(p.faces.size()) <= global_budget)
        return checkConvexityGlobal(p, tolerance);
    return checkConvexityLocal(p, tolerance);
}

VolumeArea volumeAndArea(const ConvexPolyhedron& p) {
    VolumeArea out;
    if (p.vertices.empty()) return out;
    const Vec3 ref = p.vertices[0];
    for (const auto& face : p.faces) {
        const Vec3 a = p.vertices[face[0]] - ref;
        for (size_t i = 1; i + 1 < face.size(); ++i) {
            const Vec3 b = p.vertices[face[i]] - ref;
            const Vec3 c = p.vertices[face[i + 1]] - ref;
            out.volume += a.dot(b.cross(c)) / 6.0;
            out.area += 0.5 * (b - a).cross(c - a).norm();
        }
    }
    return out;
}

}  // namespace vroc::detail
