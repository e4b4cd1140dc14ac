// SPDX-License-Identifier: MIT
// ConvexMesh: half-edge structure, Voronoi planes and validation against closed forms.
#include "narrowphase_check.h"
#include "vroc/core/errors.h"

namespace vroc::native::testing {
namespace {

TEST(ConvexMesh, BoxHasEulerCountsAndConsistentHalfEdges) {
    const ConvexMesh m = ConvexMesh::box(Vec3(1, 2, 3));
    EXPECT_EQ(m.vertexCount(), 8);
    EXPECT_EQ(m.edgeCount(), 12);
    EXPECT_EQ(m.faceCount(), 6);   // merged quads, not 12 triangles
    for (int h = 0; h < m.halfEdgeCount(); ++h) {
        EXPECT_EQ(m.origin(ConvexMesh::twin(h)), m.destination(h));
        EXPECT_EQ(m.origin(m.next(h)), m.destination(h));
        EXPECT_NEAR(m.edgeLength(h), (m.position(m.destination(h)) - m.position(m.origin(h))).norm(), 1e-15);
        // The face-edge plane normal lies in the face and points away from the face centre.
        EXPECT_NEAR(m.sideNormal(h).dot(m.faceNormal(m.face(h))), 0.0, 1e-15);
    }
    EXPECT_EQ(m.supportVertex(Vec3(1, 1, 1)), m.supportVertex(Vec3(1, 1, 1), 3));
    EXPECT_TRUE(m.position(m.supportVertex(Vec3(1, 1, 1))).isApprox(Vec3(1, 2, 3)));
}

TEST(ConvexMesh, RejectsOpenAndInconsistentInput) {
    ConvexPolyhedron box = ConvexPolyhedron::box(Vec3(1, 1, 1));
    ConvexPolyhedron open = box;
    open.faces.pop_back();
    open.face_normals.pop_back();
    open.face_offsets.pop_back();
    EXPECT_THROW(ConvexMesh::fromPolyhedron(open), GeometryError);
    ConvexPolyhedron flipped = box;
    std::reverse(flipped.faces[0].begin(), flipped.faces[0].end());
    EXPECT_THROW(ConvexMesh::fromPolyhedron(flipped), GeometryError);
    ConvexPolyhedron dented = box;
    dented.vertices[0] *= 0.5;   // a vertex pulled inwards: non-planar faces / not convex
    EXPECT_THROW(ConvexMesh::fromPolyhedron(dented), GeometryError);
}

TEST(ConvexMesh, RandomHullsRoundTrip) {
    std::mt19937_64 rng(41);
    for (int i = 0; i < 50; ++i) {
        const ConvexPolyhedron p = randomHull(rng, 4 + i * 5, 1.0);
        const ConvexMesh m = ConvexMesh::fromPolyhedron(p);
        EXPECT_EQ(m.vertexCount() - m.edgeCount() + m.faceCount(), 2);
        EXPECT_EQ(m.toPolyhedron().faces.size(), p.faces.size());
    }
}

}  // namespace
}  // namespace vroc::native::testing
