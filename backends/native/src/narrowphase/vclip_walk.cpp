// SPDX-License-Identifier: MIT
// V-Clip states. Each handler looks at one feature pair and either moves one feature to a
// neighbour (Continue), accepts the pair (Done) or reports contact (Penetration). Handlers are
// written once for "X against Y" and called with the bodies swapped for the mirrored states.
#include "narrowphase/vclip_walk.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/closest_points.h"

namespace vroc::native {
namespace {

enum class Step : std::uint8_t { Continue, Done, Penetration };

/// An edge whose direction has |cos| below this against a face normal counts as parallel to it
/// (rounding of unit vectors is ~1e-16; the distance this can miss is 1e-12 x edge length).
constexpr double kParallelSlope = 1e-12;

/// One body as the walk sees it: its mesh and the map from the other body's frame into its own.
struct Side {
    const ConvexMesh& mesh;
    const RelativeFrame& from_other;
};

/// Rounding noise of d . (x - c) for a segment d whose points have coordinates up to `extent`.
double slopeNoise(const Vec3& d, double extent) { return 64.0 * std::numeric_limits<double>::epsilon() * d.norm() * extent; }

/// Rounding noise of a distance between points with coordinates up to `extent`: pairs closer
/// than this are in contact (their Voronoi-plane signs are noise, e.g. coincident hulls).
double pointNoise(double extent) { return 64.0 * std::numeric_limits<double>::epsilon() * extent; }

double extentOf(const Vec3& a, const Vec3& b, const Vec3& p, const Vec3& q) {
    return std::max({a.lpNorm<Eigen::Infinity>(), b.lpNorm<Eigen::Infinity>(), p.lpNorm<Eigen::Infinity>(),
                     q.lpNorm<Eigen::Infinity>()});
}

Feature vertexFeature(int v) { return {FeatureType::Vertex, v}; }
Feature edgeFeature(int h) { return {FeatureType::Edge, h}; }
Feature faceFeature(int f) { return {FeatureType::Face, f}; }

/// Mirtich's clipEdge: the segment x(l) = a + l (b - a), l in [0, 1], against a feature's
/// Voronoi planes. A plane value is the signed distance, positive = outside the region.
struct Clip {
    double lo = 0.0, hi = 1.0;
    Feature n_lo, n_hi;   ///< neighbour across the plane that set lo / hi (None: segment end)
    Feature excluder;     ///< the neighbour whose plane alone excludes the whole segment

    /// Returns true when this plane alone excludes the segment (simple exclusion).
    bool plane(double da, double db, Feature neighbour) {
        if (da > 0.0 && db > 0.0) {
            excluder = neighbour;
            return true;
        }
        if (da > 0.0) {
            const double l = da / (da - db);
            if (l > lo) { lo = l; n_lo = neighbour; }
        } else if (db > 0.0) {
            const double l = da / (da - db);
            if (l < hi) { hi = l; n_hi = neighbour; }
        }
        return false;
    }
    bool compoundExcluded() const { return lo > hi; }
};

/// After a clip that did not exclude: the derivative of the distance to the clipped feature at
/// the clip ends picks the neighbour to move to (None: the pair stays). `slope(l)` is the sign
/// carrier d/dl |x(l) - feature| up to a positive factor.
///
/// The one concession to floating point: a slope within `noise` of zero counts as zero. At a
/// stationary clip point (parallel faces, edges crossing above a face) the exact slope is 0 and
/// the computed one is rounding of the operands; obeying its sign would leave a pair for one of
/// equal distance and higher dimension and cycle. Stopping there costs at most noise^2/distance.
template <class Slope>
Feature derivativeCheck(const Clip& c, Slope slope, double noise) {
    if (c.n_lo.type != FeatureType::None && slope(c.lo) > noise) return c.n_lo;
    if (c.n_hi.type != FeatureType::None && slope(c.hi) < -noise) return c.n_hi;
    if (c.compoundExcluded()) return c.n_lo.type != FeatureType::None ? c.n_lo : c.n_hi;   // defensive
    return {};
}

Step vertexVertex(const Side& x, Feature& fx, const Side& y, Feature& fy) {
    const Vec3& vx = x.mesh.position(fx.index);
    const Vec3& vy = y.mesh.position(fy.index);
    const Vec3 vy_in_x = x.from_other.apply(vy);
    if ((vy_in_x - vx).norm() <= pointNoise(extentOf(vx, vy_in_x, vx, vx))) return Step::Penetration;
    const int first_x = x.mesh.vertexEdge(fx.index);
    for (int h = first_x;;) {
        if (x.mesh.edgeDir(h).dot(vy_in_x - vx) > 0.0) { fx = edgeFeature(h); return Step::Continue; }
        if ((h = x.mesh.nextAroundOrigin(h)) == first_x) break;
    }
    const Vec3 vx_in_y = y.from_other.apply(vx);
    const int first_y = y.mesh.vertexEdge(fy.index);
    for (int h = first_y;;) {
        if (y.mesh.edgeDir(h).dot(vx_in_y - vy) > 0.0) { fy = edgeFeature(h); return Step::Continue; }
        if ((h = y.mesh.nextAroundOrigin(h)) == first_y) break;
    }
    return Step::Done;
}

/// Vertex fv of x against edge fe of y.
Step vertexEdge(const Side& x, Feature& fv, const Side& y, Feature& fe) {
    const ConvexMesh& my = y.mesh;
    const int h = fe.index;
    const Vec3& p = my.position(my.origin(h));
    const Vec3& q = my.position(my.destination(h));
    const Vec3 v_in_y = y.from_other.apply(x.mesh.position(fv.index));
    if ((v_in_y - (p + closestOnSegment(v_in_y, p, q) * (q - p))).norm() <= pointNoise(extentOf(v_in_y, p, q, q)))
        return Step::Penetration;   // the vertex is on the edge
    // 1. The vertex against the edge's region (vertex-edge planes first, then face-edge planes).
    if (my.edgeDir(h).dot(v_in_y - p) < 0.0) { fe = vertexFeature(my.origin(h)); return Step::Continue; }
    if (my.edgeDir(h).dot(v_in_y - q) > 0.0) { fe = vertexFeature(my.destination(h)); return Step::Continue; }
    if (my.sideNormal(h).dot(v_in_y - p) < 0.0) { fe = faceFeature(my.face(h)); return Step::Continue; }
    if (my.sideNormal(h ^ 1).dot(v_in_y - q) < 0.0) { fe = faceFeature(my.face(h ^ 1)); return Step::Continue; }
    // 2. The edge clipped against the vertex's region (a cone of vertex-edge planes).
    const ConvexMesh& mx = x.mesh;
    const Vec3& v = mx.position(fv.index);
    const Vec3 a = x.from_other.apply(p), b = x.from_other.apply(q);
    Clip clip;
    const int first = mx.vertexEdge(fv.index);
    for (int g = first;;) {
        if (clip.plane(mx.edgeDir(g).dot(a - v), mx.edgeDir(g).dot(b - v), edgeFeature(g))) {
            fv = clip.excluder;
            return Step::Continue;
        }
        if ((g = mx.nextAroundOrigin(g)) == first) break;
    }
    const Vec3 d = b - a;
    const Feature next =
        derivativeCheck(clip, [&](double l) { return d.dot(a + l * d - v); }, slopeNoise(d, extentOf(a, b, v, v)));
    if (next.type == FeatureType::None) return Step::Done;
    fv = next;
    return Step::Continue;
}

/// Clips the other edge (ends a, b in x's frame) against edge fx's region and moves fx if
/// needed. Mirtich's order matters: the vertex-edge planes and their derivative check first,
/// then the face-edge planes (continuing the same clip interval). Simple exclusion by a
/// face-edge plane only lowers the distance once the vertex-edge check has passed.
bool edgeAgainstEdgeRegion(const ConvexMesh& mx, Feature& fx, const Vec3& a, const Vec3& b) {
    const int h = fx.index;
    const Vec3& p = mx.position(mx.origin(h));
    const Vec3& q = mx.position(mx.destination(h));
    const Vec3& u = mx.edgeDir(h);
    const Vec3 d = b - a;
    auto slope = [&](double l) {
        const Vec3 xl = a + l * d;
        return d.dot(xl - (p + closestOnSegment(xl, p, q) * (q - p)));
    };
    const double noise = slopeNoise(d, extentOf(a, b, p, q));
    Clip clip;
    if (clip.plane(-u.dot(a - p), -u.dot(b - p), vertexFeature(mx.origin(h))) ||
        clip.plane(u.dot(a - q), u.dot(b - q), vertexFeature(mx.destination(h)))) {
        fx = clip.excluder;
        return true;
    }
    Feature next = derivativeCheck(clip, slope, noise);
    if (next.type == FeatureType::None) {
        if (clip.plane(-mx.sideNormal(h).dot(a - p), -mx.sideNormal(h).dot(b - p), faceFeature(mx.face(h))) ||
            clip.plane(-mx.sideNormal(h ^ 1).dot(a - q), -mx.sideNormal(h ^ 1).dot(b - q), faceFeature(mx.face(h ^ 1)))) {
            fx = clip.excluder;
            return true;
        }
        next = derivativeCheck(clip, slope, noise);
    }
    if (next.type == FeatureType::None) return false;
    fx = next;
    return true;
}

Step edgeEdge(const Side& x, Feature& fx, const Side& y, Feature& fy) {
    const ConvexMesh& mx = x.mesh;
    const ConvexMesh& my = y.mesh;
    if (edgeAgainstEdgeRegion(mx, fx, x.from_other.apply(my.position(my.origin(fy.index))),
                              x.from_other.apply(my.position(my.destination(fy.index)))))
        return Step::Continue;
    if (edgeAgainstEdgeRegion(my, fy, y.from_other.apply(mx.position(mx.origin(fx.index))),
                              y.from_other.apply(mx.position(mx.destination(fx.index)))))
        return Step::Continue;
    return Step::Done;
}

/// The edge of face f closest to segment ab (why a search: moving to the edge whose plane was
/// violated could raise the distance; the closest boundary edge keeps it, Mirtich's rule).
int closestFaceEdge(const ConvexMesh& m, int f, const Vec3& a, const Vec3& b) {
    int best = -1;
    double best_d2 = std::numeric_limits<double>::infinity();
    int h = m.faceEdge(f);
    for (int k = 0; k < m.faceSize(f); ++k, h = m.next(h)) {
        const Vec3& p = m.position(m.origin(h));
        const Vec3& q = m.position(m.destination(h));
        const SegmentParams st = closestSegmentSegment(a, b, p, q);
        const double d2 = (a + st.s * (b - a) - p - st.t * (q - p)).squaredNorm();
        if (d2 < best_d2) { best_d2 = d2; best = h; }
    }
    return best;
}

/// The V-F local minimum: the vertex is under the face plane, inside its prism, and no edge
/// leads up. Scan all faces (O(n)): inside all planes -> penetration, else jump to the face
/// with the largest signed distance (Mirtich; Ericson RTCD 9.2).
Step escapeLocalMinimum(const ConvexMesh& m, Feature& ff, const Vec3& v) {
    int best = -1;
    double best_d = 0.0;
    for (int f = 0; f < m.faceCount(); ++f) {
        const double d = m.faceDistance(f, v);
        if (d > best_d) { best_d = d; best = f; }
    }
    if (best < 0) return Step::Penetration;
    ff = faceFeature(best);
    return Step::Continue;
}

/// Vertex fv of x against face ff of y.
Step vertexFace(const Side& x, Feature& fv, const Side& y, Feature& ff) {
    const ConvexMesh& my = y.mesh;
    const int f = ff.index;
    const Vec3 v = y.from_other.apply(x.mesh.position(fv.index));
    int h = my.faceEdge(f);
    for (int k = 0; k < my.faceSize(f); ++k, h = my.next(h))
        if (my.sideNormal(h).dot(v - my.position(my.origin(h))) > 0.0) {
            ff = edgeFeature(closestFaceEdge(my, f, v, v));
            return Step::Continue;
        }
    const double dist = my.faceDistance(f, v);
    if (std::abs(dist) <= pointNoise(extentOf(v, v, v, v) + std::abs(my.faceOffset(f))))
        return Step::Penetration;   // the vertex is on the face: touching at least; MPR measures
    const Vec3 n_in_x = x.from_other.rotate(my.faceNormal(f));
    const ConvexMesh& mx = x.mesh;
    const int first = mx.vertexEdge(fv.index);
    for (int g = first;;) {   // an edge of the vertex along which |dist| decreases
        const double slope = mx.edgeDir(g).dot(n_in_x);   // unit vectors: rounding ~1e-16
        if ((dist > 0.0 && slope < -kParallelSlope) || (dist < 0.0 && slope > kParallelSlope)) { fv = edgeFeature(g); return Step::Continue; }
        if ((g = mx.nextAroundOrigin(g)) == first) break;
    }
    if (dist > 0.0) return Step::Done;
    return escapeLocalMinimum(my, ff, v);
}

/// Edge fe of x against face ff of y (never terminal: it always lowers dimension or reports).
Step edgeFace(const Side& x, Feature& fe, const Side& y, Feature& ff) {
    const ConvexMesh& mx = x.mesh;
    const ConvexMesh& my = y.mesh;
    const int f = ff.index;
    const Vec3 a = y.from_other.apply(mx.position(mx.origin(fe.index)));
    const Vec3 b = y.from_other.apply(mx.position(mx.destination(fe.index)));
    Clip clip;
    bool excluded = false;
    int h = my.faceEdge(f);
    for (int k = 0; k < my.faceSize(f) && !excluded; ++k, h = my.next(h)) {
        const Vec3& p = my.position(my.origin(h));
        excluded = clip.plane(my.sideNormal(h).dot(a - p), my.sideNormal(h).dot(b - p), edgeFeature(h));
    }
    if (excluded || clip.compoundExcluded()) {
        ff = edgeFeature(closestFaceEdge(my, f, a, b));
        return Step::Continue;
    }
    const Vec3 d = b - a;
    const double d_lo = my.faceDistance(f, a + clip.lo * d);
    const double d_hi = my.faceDistance(f, a + clip.hi * d);
    const double noise = pointNoise(extentOf(a, b, a, a) + std::abs(my.faceOffset(f)));
    if ((d_lo <= noise && d_hi >= -noise) || (d_lo >= -noise && d_hi <= noise)) return Step::Penetration;
    const double rising = (d_lo > 0.0 ? 1.0 : -1.0) * my.faceNormal(f).dot(d);   // d|dist|/dl sign
    if (rising >= 0.0) {
        if (clip.n_lo.type != FeatureType::None) ff = clip.n_lo;
        else fe = vertexFeature(mx.origin(fe.index));
    } else {
        if (clip.n_hi.type != FeatureType::None) ff = clip.n_hi;
        else fe = vertexFeature(mx.destination(fe.index));
    }
    return Step::Continue;
}

Vec3 pointOf(const ConvexMesh& m, int v) { return m.position(v); }

/// Closest points of a terminal pair, both in A's frame.
void closestPoints(const ConvexMesh& a, Feature fa, const ConvexMesh& b, Feature fb,
                   const RelativeFrame& b_to_a, const RelativeFrame& a_to_b, Vec3& pa, Vec3& pb) {
    auto seg = [](const ConvexMesh& m, int h, const RelativeFrame* into, Vec3& p, Vec3& q) {
        p = m.position(m.origin(h));
        q = m.position(m.destination(h));
        if (into) { p = into->apply(p); q = into->apply(q); }
    };
    using T = FeatureType;
    if (fa.type == T::Vertex && fb.type == T::Vertex) {
        pa = pointOf(a, fa.index);
        pb = b_to_a.apply(pointOf(b, fb.index));
    } else if (fa.type == T::Vertex && fb.type == T::Edge) {
        pa = pointOf(a, fa.index);
        Vec3 p, q;
        seg(b, fb.index, &b_to_a, p, q);
        pb = p + closestOnSegment(pa, p, q) * (q - p);
    } else if (fa.type == T::Edge && fb.type == T::Vertex) {
        pb = b_to_a.apply(pointOf(b, fb.index));
        Vec3 p, q;
        seg(a, fa.index, nullptr, p, q);
        pa = p + closestOnSegment(pb, p, q) * (q - p);
    } else if (fa.type == T::Edge && fb.type == T::Edge) {
        Vec3 p0, p1, q0, q1;
        seg(a, fa.index, nullptr, p0, p1);
        seg(b, fb.index, &b_to_a, q0, q1);
        const SegmentParams st = closestSegmentSegment(p0, p1, q0, q1);
        pa = p0 + st.s * (p1 - p0);
        pb = q0 + st.t * (q1 - q0);
    } else if (fa.type == T::Vertex && fb.type == T::Face) {
        pa = pointOf(a, fa.index);
        const Vec3 v = a_to_b.apply(pa);
        pb = b_to_a.apply(v - b.faceDistance(fb.index, v) * b.faceNormal(fb.index));
    } else {   // Face - Vertex
        const Vec3 v = pointOf(b, fb.index);
        pb = b_to_a.apply(v);
        pa = pb - a.faceDistance(fa.index, pb) * a.faceNormal(fa.index);
    }
}

}  // namespace

int stepBound(const ConvexMesh& a, const ConvexMesh& b) { return 4 * (a.edgeCount() + b.edgeCount()) + 64; }

FeatureCache seedFeatures(const ConvexMesh& a, const ConvexMesh& b, const RelativeFrame& b_to_a) {
    const Vec3 towards_b = b_to_a.apply(b.centroid()) - a.centroid();   // in A's frame
    const Vec3 towards_a_in_b = -(b_to_a.rotation.transpose() * towards_b);
    return {vertexFeature(a.supportVertex(towards_b)), vertexFeature(b.supportVertex(towards_a_in_b))};
}

WalkResult vclipWalk(const ConvexMesh& a, const ConvexMesh& b, const RelativeFrame& b_to_a,
                     Feature fa, Feature fb, int max_steps) {
    const RelativeFrame a_to_b = b_to_a.inverse();
    const Side sa{a, b_to_a}, sb{b, a_to_b};
    WalkResult r;
    for (r.steps = 0; r.steps <= max_steps; ++r.steps) {
        Step s = Step::Continue;
        switch (static_cast<int>(fa.type) * 4 + static_cast<int>(fb.type)) {
            case 0: s = vertexVertex(sa, fa, sb, fb); break;   // V-V
            case 1: s = vertexEdge(sa, fa, sb, fb); break;     // V-E
            case 2: s = vertexFace(sa, fa, sb, fb); break;     // V-F
            case 4: s = vertexEdge(sb, fb, sa, fa); break;     // E-V
            case 5: s = edgeEdge(sa, fa, sb, fb); break;       // E-E
            case 6: s = edgeFace(sa, fa, sb, fb); break;       // E-F
            case 8: s = vertexFace(sb, fb, sa, fa); break;     // F-V
            case 9: s = edgeFace(sb, fb, sa, fa); break;       // F-E
            case 10: fa = vertexFeature(a.origin(a.faceEdge(fa.index))); break;   // F-F: drop to V-F
            default: {   // a missing feature: seed afresh
                const FeatureCache seed = seedFeatures(a, b, b_to_a);
                fa = seed.a;
                fb = seed.b;
            }
        }
        if (s == Step::Continue) continue;
        r.a = fa;
        r.b = fb;
        if (s == Step::Penetration) {
            r.outcome = WalkOutcome::Penetrating;
            return r;
        }
        closestPoints(a, fa, b, fb, b_to_a, a_to_b, r.point_a, r.point_b);
        r.distance = (r.point_b - r.point_a).norm();
        // A distance at the rounding level of the coordinates is contact: its direction is noise
        // (coincident hulls), so MPR decides between touching and overlap.
        const double noise = slopeNoise(Vec3::UnitX(), extentOf(r.point_a, r.point_b, Vec3::Zero(), Vec3::Zero()));
        r.outcome = r.distance > noise ? WalkOutcome::Separated : WalkOutcome::Penetrating;
        return r;
    }
    r.a = fa;
    r.b = fb;
    r.outcome = WalkOutcome::StepLimit;
    return r;
}

}  // namespace vroc::native
