// SPDX-License-Identifier: MIT
// A closed convex polyhedron as a half-edge structure with the Voronoi region planes of every
// vertex, edge and face precomputed (Lin–Canny / V-Clip features). Everything is in the mesh's
// own (local) frame, metres. Immutable after construction; share it by const reference.
//
// Layout (flat arrays, cache-friendly): half-edges come in twin pairs 2k, 2k+1 (twin = h ^ 1), so
// the undirected edge of half-edge h is h / 2. A half-edge runs origin(h) -> origin(h ^ 1) and
// belongs to the face on its left seen from outside (faces are CCW seen from outside).
//
// Voronoi planes (all unit normals, Mirtich's sign convention "positive = outside the region"):
//   vertex–edge plane of h: dot(edgeDir(h), x - vertex(origin(h))) > 0 leaves the region of the
//     vertex origin(h) towards edge h;  < 0 leaves edge h's region towards vertex origin(h).
//   face–edge plane of h:   dot(sideNormal(h), x - vertex(origin(h))) > 0 leaves the region of
//     face(h) towards edge h;  < 0 leaves edge h's region towards face(h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "vroc/core/convex_polyhedron.h"
#include "vroc/core/math.h"

namespace vroc::native {

class ConvexMesh {
public:
    /// Builds and validates (throws GeometryError with one line saying what is wrong).
    static ConvexMesh fromPolyhedron(const ConvexPolyhedron& poly);
    /// Axis-aligned box centred at the origin, half extents [m].
    static ConvexMesh box(const Vec3& half_extents);

    int vertexCount() const { return static_cast<int>(positions_.size()); }
    int halfEdgeCount() const { return static_cast<int>(he_origin_.size()); }
    int edgeCount() const { return halfEdgeCount() / 2; }
    int faceCount() const { return static_cast<int>(face_normal_.size()); }

    const Vec3& position(int v) const { return positions_[v]; }           ///< [m] local
    int vertexEdge(int v) const { return vertex_edge_[v]; }                ///< one outgoing half-edge
    /// Next outgoing half-edge around the origin of h (the ring around a vertex).
    int nextAroundOrigin(int h) const { return he_next_[h ^ 1]; }

    static int twin(int h) { return h ^ 1; }
    int origin(int h) const { return he_origin_[h]; }
    int destination(int h) const { return he_origin_[h ^ 1]; }
    int next(int h) const { return he_next_[h]; }
    int face(int h) const { return he_face_[h]; }
    const Vec3& edgeDir(int h) const { return he_dir_[h]; }               ///< unit, origin -> destination
    double edgeLength(int h) const { return he_length_[h]; }              ///< [m]
    const Vec3& sideNormal(int h) const { return he_side_[h]; }           ///< unit, in face(h)'s plane, outward

    int faceEdge(int f) const { return face_edge_[f]; }                    ///< first half-edge of face f
    int faceSize(int f) const { return face_size_[f]; }
    const Vec3& faceNormal(int f) const { return face_normal_[f]; }        ///< unit outward
    double faceOffset(int f) const { return face_offset_[f]; }             ///< [m] dot(n, x) = offset on the plane
    double faceDistance(int f, const Vec3& x) const { return face_normal_[f].dot(x) - face_offset_[f]; }

    const Vec3& centroid() const { return centroid_; }                     ///< [m] vertex average (interior point)
    double boundingRadius() const { return bounding_radius_; }             ///< [m] max |v - centroid|
    double scale() const { return scale_; }                                ///< [m] bounding-box diagonal

    /// Vertex maximising dot(dir, x), by hill climbing from `start` (exact on a convex polytope).
    int supportVertex(const Vec3& dir, int start = 0) const;

    /// The polyhedron back (for printing regression tests and for round-trip checks).
    ConvexPolyhedron toPolyhedron() const;

private:
    void build(const ConvexPolyhedron& poly);
    void computePlanes();
    void validate() const;

    std::vector<Vec3> positions_;
    std::vector<int> vertex_edge_;
    std::vector<int> he_origin_, he_next_, he_face_;
    std::vector<Vec3> he_dir_, he_side_;
    std::vector<double> he_length_;
    std::vector<int> face_edge_, face_size_;
    std::vector<Vec3> face_normal_;
    std::vector<double> face_offset_;
    Vec3 centroid_ = Vec3::Zero();
    double bounding_radius_ = 0.0;
    double scale_ = 0.0;
};

}  // namespace vroc::native
