// SPDX-License-Identifier: MIT
#include "scheduling/time_of_contact.h"

#include <algorithm>
#include <cmath>

#include "scheduling/collision_time_bound.h"

namespace vroc::native {

namespace {

struct Window {
    double low;      // [m] tol / 2
    double high;     // [m] tol
    double target;   // [m] 0.75 tol: the CA aim, in the middle of the window
};

Window windowFor(const ToiSettings& s) {
    return {0.5 * s.collision_distance, s.collision_distance, 0.75 * s.collision_distance};
}

// The CA step. A normal that is not a unit vector (degenerate narrow-phase answer) would make the
// projected bound meaningless, so the direction-free bound is used instead.
double safeStep(const DistanceSample& s, double target, const MotionBound& a, const MotionBound& b,
                double horizon) {
    const double len2 = s.normal.squaredNorm();
    if (std::isfinite(len2) && std::abs(len2 - 1.0) <= 1e-9) {
        return earliestCollisionTime(s.distance - target, s.normal, a, b, horizon);
    }
    return earliestCollisionTime(s.distance - target, a, b, horizon);
}

ToiResult finish(ToiState state, double time, const DistanceSample& sample, double sample_time,
                 ToiResult progress) {
    progress.state = state;
    progress.time = time;
    progress.sample = sample;
    progress.sample_time = sample_time;
    return progress;
}

}  // namespace

const char* toString(ToiState state) {
    switch (state) {
        case ToiState::Hit: return "hit";
        case ToiState::Separated: return "separated";
        case ToiState::Overlapped: return "overlapped";
        case ToiState::Failed: return "failed";
    }
    return "?";
}

ToiResult bisectContact(const DistanceFunction& distance, double t_a, const DistanceSample& at_a,
                        double t_b, const DistanceSample& at_b, const ToiSettings& settings) {
    const Window w = windowFor(settings);
    ToiResult progress;
    const double safe_time = t_a;   // the only time the caller vouched for
    for (int i = 0; i < settings.max_iterations; ++i) {
        const double mid = 0.5 * (t_a + t_b);
        if (!(mid > t_a && mid < t_b)) break;   // bracket exhausted in double precision
        const DistanceSample s = distance(mid);
        ++progress.iterations;
        ++progress.bisection_steps;
        if (s.distance >= w.low && s.distance <= w.high) return finish(ToiState::Hit, mid, s, mid, progress);
        if (s.distance > w.high) t_a = mid; else t_b = mid;   // NaN goes left: earlier is safer
    }
    (void)at_b;
    return finish(ToiState::Failed, safe_time, at_a, safe_time, progress);
}

ToiResult conservativeAdvancement(const DistanceFunction& distance, const MotionBound& a,
                                  const MotionBound& b, double t0, double t1,
                                  const ToiSettings& settings) {
    const Window w = windowFor(settings);
    ToiResult progress;
    double t = t0;
    DistanceSample s = distance(t);
    if (!(s.distance >= w.low)) return finish(ToiState::Overlapped, t0, s, t0, progress);
    if (s.distance <= w.high) return finish(ToiState::Hit, t0, s, t0, progress);

    while (progress.iterations < settings.max_iterations) {
        const double dt = safeStep(s, w.target, a.advanced(t - t0), b.advanced(t - t0), t1 - t);
        if (dt == kNever) return finish(ToiState::Separated, t1, s, t, progress);
        const double t_next = std::min(t + dt, t1);
        if (!(t_next > t)) break;   // no progress representable: give up at the safe time t
        const DistanceSample next = distance(t_next);
        ++progress.iterations;
        ++progress.advancement_steps;
        if (next.distance >= w.low && next.distance <= w.high) {
            return finish(ToiState::Hit, t_next, next, t_next, progress);
        }
        if (!(next.distance > w.high)) {
            // Below the window (or NaN): the bounds did not hold. Bisect [t, t_next].
            ToiSettings rest = settings;
            rest.max_iterations = settings.max_iterations - progress.iterations;
            ToiResult bis = bisectContact(distance, t, s, t_next, next, rest);
            bis.iterations += progress.iterations;
            bis.advancement_steps = progress.advancement_steps;
            return bis;
        }
        t = t_next;
        s = next;
    }
    return finish(ToiState::Failed, t, s, t, progress);
}

}  // namespace vroc::native
