// SPDX-License-Identifier: MIT
#include "vroc/harness/metrics/neutral_distance.h"

#include <algorithm>
#include <limits>

#include "world_polytope.h"

namespace vroc::harness {
namespace {

bool isSphere(const Shape& s) { return s.kind == Shape::Kind::Sphere; }

double convexPair(const Shape& a, const Pose& pa, const Shape& b, const Pose& pb) {
    if (isSphere(a) && isSphere(b)) return (pa.position - pb.position).norm() - a.radius - b.radius;
    if (isSphere(a)) return pointPolytopeDistance(pa.position, placePolytope(b, pb)) - a.radius;
    if (isSphere(b)) return pointPolytopeDistance(pb.position, placePolytope(a, pa)) - b.radius;
    return polytopeDistance(placePolytope(a, pa), placePolytope(b, pb));
}

}  // namespace

double signedDistance(const Shape& a, const Pose& pose_a, const Shape& b, const Pose& pose_b) {
    if (a.kind == Shape::Kind::Compound) {
        double best = std::numeric_limits<double>::infinity();
        for (const ShapePart& part : a.parts) best = std::min(best, signedDistance(part.shape, pose_a * part.pose, b, pose_b));
        return best;
    }
    if (b.kind == Shape::Kind::Compound) return signedDistance(b, pose_b, a, pose_a);
    return convexPair(a, pose_a, b, pose_b);
}

double pointSignedDistance(const Vec3& point, const Shape& shape, const Pose& pose) {
    if (shape.kind == Shape::Kind::Compound) {
        double best = std::numeric_limits<double>::infinity();
        for (const ShapePart& part : shape.parts) best = std::min(best, pointSignedDistance(point, part.shape, pose * part.pose));
        return best;
    }
    if (isSphere(shape)) return (point - pose.position).norm() - shape.radius;
    return pointPolytopeDistance(point, placePolytope(shape, pose));
}

double bodyDistance(const Scene& scene, int a, const Pose& pose_a, int b, const Pose& pose_b) {
    return signedDistance(scene.bodies[static_cast<std::size_t>(a)].shape, pose_a,
                          scene.bodies[static_cast<std::size_t>(b)].shape, pose_b);
}

}  // namespace vroc::harness
