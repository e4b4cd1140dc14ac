// SPDX-License-Identifier: MIT
#include "scheduling/contact_time_refinement.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "backend/part_query.h"
#include "dynamics/free_flight.h"
#include "scheduling/collision_time_bound.h"

namespace vroc::native {
namespace {

double smallest(const std::vector<DistanceSample>& gaps) {
    double d = std::numeric_limits<double>::infinity();
    for (const DistanceSample& g : gaps) d = std::isnan(g.distance) ? g.distance : std::min(d, g.distance);
    return d;
}

// One CA step for every part pair (each with its own normal): the earliest time any could close
// to `target`. Degenerate normals fall back to the direction-free bound.
double certifiedStep(const std::vector<DistanceSample>& gaps, double target, const MotionBound& a,
                     const MotionBound& b, double horizon) {
    double best = kNever;
    for (const DistanceSample& g : gaps) {
        const double len2 = g.normal.squaredNorm();
        const double dt = (std::isfinite(len2) && std::abs(len2 - 1.0) <= 1e-9)
                              ? earliestCollisionTime(g.distance - target, g.normal, a, b, horizon)
                              : earliestCollisionTime(g.distance - target, a, b, horizon);
        best = std::min(best, dt);
    }
    return best;
}

// The bracket (t_ok: gap > gap_max, t_bad: gap < 0) halved until a midpoint lands in [0, gap_max].
RefineResult bisectBack(const PartGapsFunction& gaps, double t_ok, double t_bad, double gap_max,
                        RefineResult progress, int max_queries) {
    while (progress.queries < max_queries) {
        const double mid = 0.5 * (t_ok + t_bad);
        if (!(mid > t_ok && mid < t_bad)) break;
        const double d = smallest(gaps(mid));
        ++progress.queries;
        if (d >= 0.0 && d <= gap_max) {
            progress.state = RefineState::Touching;
            progress.time = mid;
            progress.gap = d;
            return progress;
        }
        if (d > gap_max) t_ok = mid; else t_bad = mid;   // NaN goes left: earlier is safer
    }
    progress.state = RefineState::Advanced;
    progress.time = t_ok;
    return progress;
}

}  // namespace

RefineResult refineContactTime(const PartGapsFunction& gaps, const std::vector<DistanceSample>& at_t0,
                               const MotionBound& a, const MotionBound& b, double t0, double t1,
                               double gap_max, int max_queries) {
    RefineResult r;
    r.time = t0;
    r.gap = smallest(at_t0);
    const double target = 0.5 * gap_max;
    double t = t0;
    std::vector<DistanceSample> now = at_t0;
    while (r.queries < max_queries) {
        const double d = smallest(now);
        if (d >= 0.0 && d <= gap_max) {
            r.state = RefineState::Touching;
            r.time = t;
            r.gap = d;
            return r;
        }
        const double dt = certifiedStep(now, target, a.advanced(t - t0), b.advanced(t - t0), t1 - t);
        if (dt == kNever || t + dt >= t1) {
            r.state = RefineState::Clear;
            r.time = t1;
            return r;
        }
        const double t_next = t + dt;
        if (!(t_next > t)) break;
        std::vector<DistanceSample> next = gaps(t_next);
        ++r.queries;
        const double dn = smallest(next);
        if (!(dn >= 0.0)) return bisectBack(gaps, t, t_next, gap_max, r, max_queries + 60);
        t = t_next;
        r.gap = dn;
        now = std::move(next);
    }
    r.state = t > t0 ? RefineState::Advanced : RefineState::Failed;
    r.time = t;
    return r;
}

PartGapsFunction flightGaps(const RigidBody& a, const BodyShape& shape_a, const RigidBody& b,
                            const BodyShape& shape_b, const std::vector<FeatureCache>& caches,
                            const Vec3& gravity, double t0) {
    return [a, &shape_a, b, &shape_b, caches, gravity, t0](double t) {
        // The same sequence syncBody uses, so the pose matches the one the backend reaches.
        auto fly = [&](RigidBody body) {
            if (!body.is_static && t > t0) {
                advanceBallistic(body, t - t0, gravity);
                advanceTorqueFree(body, t - t0);
            }
            return body.framePose();
        };
        const Pose fa = fly(a);
        const Pose fb = fly(b);
        std::vector<FeatureCache> walk = caches;
        std::vector<DistanceSample> out;
        for (std::size_t i = 0; i < shape_a.parts.size(); ++i) {
            for (std::size_t j = 0; j < shape_b.parts.size(); ++j) {
                const ProximityResult p = queryParts(shape_a.parts[i], fa * shape_a.parts[i].local,
                                                     shape_b.parts[j], fb * shape_b.parts[j].local,
                                                     walk[i * shape_b.parts.size() + j]);
                out.push_back({p.distance, p.normal, p.point_a, p.point_b});
            }
        }
        return out;
    };
}

}  // namespace vroc::native
