// SPDX-License-Identifier: MIT
#include "narrowphase/mpr_penetration.h"

#include <algorithm>

#include <ccd/ccd.h>

namespace vroc::native {
namespace {

/// What libccd's callbacks receive: the mesh, its pose as a matrix, and the hill-climb start.
struct CcdBody {
    const ConvexMesh* mesh;
    Mat3 rotation;
    Vec3 position;
    mutable int hint;
};

void support(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* out) {
    const auto* body = static_cast<const CcdBody*>(obj);
    const Vec3 d_world(dir->v[0], dir->v[1], dir->v[2]);
    body->hint = body->mesh->supportVertex(body->rotation.transpose() * d_world, body->hint);
    const Vec3 p = body->rotation * body->mesh->position(body->hint) + body->position;
    ccdVec3Set(out, p.x(), p.y(), p.z());
}

void center(const void* obj, ccd_vec3_t* out) {
    const auto* body = static_cast<const CcdBody*>(obj);
    const Vec3 c = body->rotation * body->mesh->centroid() + body->position;
    ccdVec3Set(out, c.x(), c.y(), c.z());
}

}  // namespace

MprResult mprPenetration(const ConvexMesh& a, const Pose& pose_a, const ConvexMesh& b, const Pose& pose_b,
                         int hint_a, int hint_b) {
    CcdBody body_a{&a, pose_a.orientation.toRotationMatrix(), pose_a.position, hint_a};
    CcdBody body_b{&b, pose_b.orientation.toRotationMatrix(), pose_b.position, hint_b};
    ccd_t ccd;
    CCD_INIT(&ccd);
    ccd.support1 = support;
    ccd.support2 = support;
    ccd.center1 = center;
    ccd.center2 = center;
    ccd.max_iterations = 200;
    // MPR stops when the portal moves less than this: far below the 1e-9 m accuracy target.
    ccd.mpr_tolerance = 1e-13 * std::max(a.scale(), b.scale());
    ccd_real_t depth = 0.0;
    ccd_vec3_t dir, pos;
    MprResult r;
    // libccd: "if obj2 is translated by depth in direction dir they touch" -> dir points A -> B.
    if (ccdMPRPenetration(&body_a, &body_b, &ccd, &depth, &dir, &pos) != 0) return r;
    r.intersecting = true;
    r.depth = std::max(0.0, static_cast<double>(depth));
    r.direction = Vec3(dir.v[0], dir.v[1], dir.v[2]);
    if (!r.direction.allFinite() || r.direction.squaredNorm() == 0.0) r.direction = Vec3::UnitX();
    r.direction.normalize();
    r.position = Vec3(pos.v[0], pos.v[1], pos.v[2]);
    return r;
}

}  // namespace vroc::native
