// SPDX-License-Identifier: MIT
// vroc::Shape -> ODE geoms. Spheres and boxes are ODE's own (dCreateSphere, dCreateBox: exact
// surfaces); a compound is one geom per part, all on the same body. A hull is, by `HullGeom`:
//  - TriMesh (default): dCreateTriMesh of its faces cut into triangle fans (the same surface),
//    collided by ODE's OPCODE colliders, which give several contact points per pair;
//  - Convex: dCreateConvex of its vertices, face planes and polygons. Debian's ODE collides convex
//    geoms with libccd's MPR: one contact point per pair and step, so a resting hull rocks, sinks
//    and topples (measured in docs/ode-backend.md); kept as the alternative.
// Every geom's user data is its scene body index (the contact callback maps geoms back to bodies).
//
// Frames: a virtual body's geoms hang on its ODE body, whose frame is the centre of mass with the
// scene body's axes (ODE takes a full inertia tensor, so no principal frame is needed); their
// offsets (dGeomSetOffsetPosition/Quaternion) are the part poses relative to that frame. A real
// body has no ODE body: its geoms are placed in the world at its scene pose.
//
// A hull's ODE frame is its vertex centroid, not the part frame: libccd's MPR takes the geom origin
// as a point inside the shape, and dCreateConvex expects every face plane to have the origin on
// its inner side. (The trimesh does not care; it uses the same frame for simplicity.)
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <ode/ode.h>

#include "ode_config.h"
#include "vroc/core/shape.h"

namespace vroc::ode {

/// "" if ODE can represent `shape`; otherwise what is wrong ("hull face 3 has 2 vertices", ...).
std::string unsupportedReason(const Shape& shape);

/// Builds the geoms of bodies and owns the arrays trimesh and convex geoms point into (ODE copies
/// none of them), so the mapper must outlive every geom it made.
class ShapeMapper {
public:
    explicit ShapeMapper(HullGeom hull_geom) : hull_geom_(hull_geom) {}
    ~ShapeMapper();
    ShapeMapper(const ShapeMapper&) = delete;
    ShapeMapper& operator=(const ShapeMapper&) = delete;

    /// Geoms of a virtual body: attached to `body`, placed by `shape_in_body_frame` (shape frame
    /// -> ODE body frame). Added to `space`; `scene_index` becomes each geom's user data.
    void attach(dSpaceID space, dBodyID body, const Shape& shape, const Pose& shape_in_body_frame, int scene_index);
    /// Geoms of a real body: no ODE body, placed at `shape_in_world` (shape frame -> world).
    void place(dSpaceID space, const Shape& shape, const Pose& shape_in_world, int scene_index);

private:
    /// What a hull geom points into (ODE copies none of it).
    struct HullArrays {
        std::vector<dReal> points;          ///< x, y, z per vertex, relative to the vertex centroid
        std::vector<dReal> planes;          ///< Convex: a, b, c, d per face: a x + b y + c z = d, unit outward normal
        std::vector<unsigned int> polygons; ///< Convex: per face, vertex count then indices (counter-clockwise from outside)
        std::vector<dTriIndex> triangles;   ///< TriMesh: 3 indices per triangle, counter-clockwise from outside
        dTriMeshDataID trimesh = nullptr;   ///< TriMesh: owned
    };
    /// Calls `make(geom, pose)` for each convex part, `pose` = geom frame -> `frame`'s parent.
    template <class Make>
    void forEachPart(dSpaceID space, const Shape& shape, const Pose& frame, int scene_index, Make make);
    dGeomID convexGeom(dSpaceID space, const Shape& part, Pose& geom_in_part);
    dGeomID hullGeom(dSpaceID space, const ConvexPolyhedron& hull, const Vec3& centroid);

    HullGeom hull_geom_;
    std::vector<std::unique_ptr<HullArrays>> hulls_;
};

}  // namespace vroc::ode
