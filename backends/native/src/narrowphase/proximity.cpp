// SPDX-License-Identifier: MIT
// The queries of proximity.h: the V-Clip walk in A's frame, the separating axis test (MPR for
// large meshes) for penetration depth, results moved to world coordinates.
#include "narrowphase/proximity.h"

#include <limits>
#include <vector>

#include "geometry/convex_mesh.h"
#include "narrowphase/mpr_penetration.h"
#include "narrowphase/sat_penetration.h"
#include "narrowphase/point_mesh_walk.h"
#include "narrowphase/vclip_walk.h"

namespace vroc::native {
namespace {

bool validFeature(const ConvexMesh& m, Feature f) {
    switch (f.type) {
        case FeatureType::Vertex: return f.index >= 0 && f.index < m.vertexCount();
        case FeatureType::Edge: return f.index >= 0 && f.index < m.halfEdgeCount();
        case FeatureType::Face: return f.index >= 0 && f.index < m.faceCount();
        default: return false;
    }
}

/// Direction between centroids (world), for the rare answers that have no better normal.
Vec3 centroidDirection(const ConvexMesh& a, const Pose& pose_a, const ConvexMesh& b, const Pose& pose_b) {
    const Vec3 d = pose_b.apply(b.centroid()) - pose_a.apply(a.centroid());
    return d.squaredNorm() > 0.0 ? Vec3(d.normalized()) : Vec3(Vec3::UnitX());
}

/// A vertex of feature f (a start for support hill climbs).
int vertexOf(const ConvexMesh& m, Feature f) {
    switch (f.type) {
        case FeatureType::Vertex: return f.index;
        case FeatureType::Edge: return m.origin(f.index);
        case FeatureType::Face: return m.origin(m.faceEdge(f.index));
        default: return 0;
    }
}

/// Separation of A and B along the world direction n (from A towards B): min over B of n·x minus
/// max over A of n·x. >= 0 means n separates them; the supporting vertices are returned.
double separationAlong(const ConvexMesh& a, const Pose& pose_a, const ConvexMesh& b, const Pose& pose_b,
                       const Vec3& n, int hint_a, int hint_b, Vec3& support_b) {
    const int va = a.supportVertex(pose_a.orientation.conjugate() * n, hint_a);
    const int vb = b.supportVertex(pose_b.orientation.conjugate() * (-n), hint_b);
    support_b = pose_b.apply(b.position(vb));
    return n.dot(support_b) - n.dot(pose_a.apply(a.position(va)));
}

/// Candidate contact normals (world, from A to B) from the walk's final features: the faces of
/// A's feature and of its incident faces (outward), those of B (inward), the edge-edge cross
/// product (both signs). The best of them is the normal of an exactly touching pair.
void featureNormals(const ConvexMesh& m, const Pose& pose, Feature f, double sign, std::vector<Vec3>& out) {
    auto add = [&](int face) { out.push_back(sign * pose.rotate(m.faceNormal(face))); };
    switch (f.type) {
        case FeatureType::Face: add(f.index); break;
        case FeatureType::Edge: add(m.face(f.index)); add(m.face(ConvexMesh::twin(f.index))); break;
        case FeatureType::Vertex: {
            const int first = m.vertexEdge(f.index);
            int h = first;
            for (int guard = 0; guard < 64; ++guard) {
                add(m.face(h));
                h = m.nextAroundOrigin(h);
                if (h == first) break;
            }
            break;
        }
        default: break;
    }
}

Vec3 edgeDirection(const ConvexMesh& m, const Pose& pose, int h) {
    return pose.rotate(m.position(m.destination(h)) - m.position(m.origin(h)));
}

/// The best-separating of the axes the walk's final features offer (featureNormals, and the
/// edge-edge cross product): its separation (>= the distance only for a separating axis), the axis
/// (world, from A to B) and B's supporting point along it.
struct FeatureAxis {
    double separation = -std::numeric_limits<double>::infinity();
    Vec3 normal = Vec3::UnitZ();
    Vec3 support_b = Vec3::Zero();
};

FeatureAxis bestFeatureAxis(const ConvexMesh& a, const Pose& pose_a, const ConvexMesh& b, const Pose& pose_b,
                            const FeatureCache& near) {
    thread_local std::vector<Vec3> axes;   // per worker, keeps its capacity: no allocation once warm
    axes.clear();
    featureNormals(a, pose_a, near.a, 1.0, axes);
    featureNormals(b, pose_b, near.b, -1.0, axes);
    if (near.a.type == FeatureType::Edge && near.b.type == FeatureType::Edge) {
        const Vec3 c = edgeDirection(a, pose_a, near.a.index).cross(edgeDirection(b, pose_b, near.b.index));
        const double len = c.norm();
        if (len > 1e-9 * a.scale() * b.scale()) {
            axes.push_back(c / len);
            axes.push_back(-c / len);
        }
    }
    FeatureAxis best;
    for (const Vec3& n : axes) {
        Vec3 pb;
        const double sep = separationAlong(a, pose_a, b, pose_b, n, vertexOf(a, near.a), vertexOf(b, near.b), pb);
        if (sep > best.separation) best = {sep, n, pb};
    }
    return best;
}

/// Contact when the walk saw zero distance: if some candidate axis separates A and B to within a
/// few ulp of the coordinates, the pair is touching, not penetrating, and that axis (a face
/// normal, or an edge-edge cross product) is the normal. MPR's direction for a zero depth is
/// arbitrary (e.g. horizontal for a box resting exactly on a floor), so it is not used then.
bool touchingResult(const ConvexMesh& a, const Pose& pose_a, const ConvexMesh& b, const Pose& pose_b,
                    const FeatureCache& near, ProximityResult& r) {
    const double coords = a.scale() + b.scale() + pose_a.position.cwiseAbs().maxCoeff() +
                          pose_b.position.cwiseAbs().maxCoeff();
    const double tol = 64.0 * std::numeric_limits<double>::epsilon() * coords;
    const FeatureAxis best = bestFeatureAxis(a, pose_a, b, pose_b, near);
    r.normal = best.normal;
    r.point_a = r.point_b = best.support_b;
    if (!(best.separation >= -tol)) return false;
    r.distance = 0.0;
    r.penetrating = false;
    return true;
}

/// Below this fraction of the two meshes' scales a separated pair's direction between its closest
/// points is noise (two parallel edges of a box set exactly on another, 2e-11 m apart, gave a normal
/// 62 deg off the vertical: tests/backends/native/narrowphase_touching_test.cpp).
constexpr double kNearTouching = 1e-6;
/// A feature's axis stands for that direction if it separates them to within this fraction of the
/// scales of the distance (the most any axis can separate them by).
constexpr double kAxisSlack = 1e-9;

/// A separated pair nearly touching: a face normal or an edge-edge cross product of its features
/// that separates it as well as the closest points' direction does (to kAxisSlack) is its normal.
void nearTouchingNormal(const ConvexMesh& a, const Pose& pose_a, const ConvexMesh& b, const Pose& pose_b,
                        const FeatureCache& near, ProximityResult& r) {
    const double scales = a.scale() + b.scale();
    if (!(r.distance < kNearTouching * scales)) return;
    const FeatureAxis best = bestFeatureAxis(a, pose_a, b, pose_b, near);
    if (best.separation >= r.distance - kAxisSlack * scales) r.normal = best.normal;
}

ProximityResult penetrationResult(const ConvexMesh& a, const Pose& pose_a, const ConvexMesh& b, const Pose& pose_b,
                                  const FeatureCache& near) {
    ProximityResult r;
    if (touchingResult(a, pose_a, b, pose_b, near, r)) return r;
    r.penetrating = true;
    // Exact (the separating axis test) where its edge loop is affordable, else MPR's estimate.
    bool overlap = false;
    if (satAffordable(a, b)) {
        const SatPenetration m = satPenetration(a, pose_a, b, pose_b);
        if ((overlap = m.depth > 0.0)) {
            r.distance = -m.depth;
            r.normal = m.normal;
            r.point_a = m.point_a;
            r.point_b = m.point_b;
        }
    } else {
        const MprResult m = mprPenetration(a, pose_a, b, pose_b, vertexOf(a, near.a), vertexOf(b, near.b));
        if ((overlap = m.intersecting)) {
            r.distance = -m.depth;
            r.normal = m.direction;
            r.point_a = m.position + 0.5 * m.depth * m.direction;
            r.point_b = m.position - 0.5 * m.depth * m.direction;
        }
    }
    if (!overlap) {   // exactly touching: the walk saw zero distance, the depth query no overlap
        r.distance = 0.0;
        r.normal = centroidDirection(a, pose_a, b, pose_b);
        r.point_a = r.point_b = pose_a.apply(a.position(a.supportVertex(pose_a.orientation.conjugate() * r.normal)));
    }
    return r;
}

}  // namespace

ProximityResult queryMeshMesh(const ConvexMesh& a, const Pose& pose_a, const ConvexMesh& b, const Pose& pose_b,
                              FeatureCache& cache) {
    const Mat3 rot_a = pose_a.orientation.toRotationMatrix();
    const Mat3 rot_at = rot_a.transpose();
    const RelativeFrame b_to_a{rot_at * pose_b.orientation.toRotationMatrix(), rot_at * (pose_b.position - pose_a.position)};
    FeatureCache start = cache;
    if (!validFeature(a, start.a) || !validFeature(b, start.b)) start = seedFeatures(a, b, b_to_a);
    const int bound = stepBound(a, b);
    WalkResult w = vclipWalk(a, b, b_to_a, start.a, start.b, bound);
    int steps = w.steps;
    bool converged = true;
    if (w.outcome == WalkOutcome::StepLimit) {   // never expected: retry from a cold seed
        converged = false;
        const FeatureCache seed = seedFeatures(a, b, b_to_a);
        w = vclipWalk(a, b, b_to_a, seed.a, seed.b, bound);
        steps += w.steps;
    }
    cache = {w.a, w.b};
    ProximityResult r;
    if (w.outcome == WalkOutcome::Separated) {
        r.distance = w.distance;
        r.point_a = rot_a * w.point_a + pose_a.position;   // the matrix is at hand: cheaper than the quaternion
        r.point_b = rot_a * w.point_b + pose_a.position;
        // From the local difference (the one the distance came from): unit to rounding even when the
        // distance is tiny, unlike the difference of the two rounded world points.
        r.normal = rot_a * ((w.point_b - w.point_a) / w.distance);
        nearTouchingNormal(a, pose_a, b, pose_b, cache, r);
    } else {   // Penetrating, or the retry failed too: MPR gives the verdict and the depth
        r = penetrationResult(a, pose_a, b, pose_b, cache);
        if (w.outcome == WalkOutcome::StepLimit && r.distance == 0.0) {
            cache = {};   // no trustworthy pair: report touching-or-apart as contact, counted
        }
    }
    r.walk_steps = steps;
    r.converged = converged;
    return r;
}

ProximityResult querySphereMesh(const Vec3& center, double radius, const ConvexMesh& mesh, const Pose& pose,
                                FeatureCache& cache) {
    const Vec3 local = pose.applyInverse(center);
    const PointWalkResult w = closestFeatureToPoint(mesh, local, cache.b);
    cache = {Feature{}, w.feature};
    ProximityResult r;
    r.walk_steps = w.steps;
    r.converged = w.converged;
    r.distance = w.signed_distance - radius;
    r.penetrating = r.distance <= 0.0;
    r.point_b = pose.apply(w.closest);
    if (w.signed_distance > 0.0) {
        r.normal = (r.point_b - center) / (r.point_b - center).norm();
    } else if (w.feature.type == FeatureType::Face) {   // centre inside: push out through the nearest face
        r.normal = -pose.rotate(mesh.faceNormal(w.feature.index));
    } else {
        const Vec3 d = pose.apply(mesh.centroid()) - center;
        r.normal = d.squaredNorm() > 0.0 ? Vec3(d.normalized()) : Vec3(Vec3::UnitX());
    }
    r.point_a = center + radius * r.normal;
    return r;
}

ProximityResult querySphereSphere(const Vec3& center_a, double radius_a, const Vec3& center_b, double radius_b) {
    ProximityResult r;
    const Vec3 d = center_b - center_a;
    const double len = d.norm();
    r.normal = len > 0.0 ? Vec3(d / len) : Vec3(Vec3::UnitX());
    r.distance = len - radius_a - radius_b;
    r.penetrating = r.distance <= 0.0;
    r.point_a = center_a + radius_a * r.normal;
    r.point_b = center_b - radius_b * r.normal;
    return r;
}

}  // namespace vroc::native
