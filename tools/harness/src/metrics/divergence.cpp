// SPDX-License-Identifier: MIT
#include "vroc/harness/metrics/divergence.h"

#include <algorithm>
#include <cmath>

namespace vroc::harness {

double maxPositionError(const Scene& scene, std::span<const BodyState> a, std::span<const BodyState> b) {
    double worst = 0;
    for (std::size_t i = 0; i < scene.bodies.size() && i < a.size() && i < b.size(); ++i)
        if (scene.bodies[i].isDynamic()) worst = std::max(worst, (a[i].pose.position - b[i].pose.position).norm());
    return worst;
}

double maxAngleError(const Scene& scene, std::span<const BodyState> a, std::span<const BodyState> b) {
    double worst = 0;
    for (std::size_t i = 0; i < scene.bodies.size() && i < a.size() && i < b.size(); ++i) {
        if (!scene.bodies[i].isDynamic()) continue;
        const double dot = std::abs(a[i].pose.orientation.normalized().dot(b[i].pose.orientation.normalized()));
        worst = std::max(worst, 2.0 * std::acos(std::min(1.0, dot)));
    }
    return worst;
}

Divergence divergence(const Scene& scene, const RunTrace& a, const RunTrace& b) {
    Divergence d;
    const std::size_t n = std::min(a.states.size(), b.states.size());
    d.per_body_max.assign(scene.virtualBodyCount(), 0.0);
    for (std::size_t f = 0; f < n; ++f) {
        d.t.push_back(a.times[f]);
        d.distance.push_back(maxPositionError(scene, a.states[f], b.states[f]));
        std::size_t v = 0;
        for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
            if (!scene.bodies[i].isDynamic()) continue;
            d.per_body_max[v] = std::max(d.per_body_max[v], (a.states[f][i].pose.position - b.states[f][i].pose.position).norm());
            ++v;
        }
    }
    return d;
}

std::optional<double> horizon(std::span<const double> t, std::span<const double> spread, double delta) {
    for (std::size_t i = 0; i < t.size() && i < spread.size(); ++i)
        if (spread[i] > delta) return t[i];
    return std::nullopt;
}

std::optional<double> ftle(std::span<const double> t, std::span<const double> spread, double lo, double hi) {
    double n = 0, st = 0, sy = 0, stt = 0, sty = 0;
    for (std::size_t i = 0; i < t.size() && i < spread.size(); ++i) {
        if (!(spread[i] > lo && spread[i] < hi)) continue;
        const double y = std::log(spread[i]);
        n += 1;
        st += t[i];
        sy += y;
        stt += t[i] * t[i];
        sty += t[i] * y;
    }
    const double denom = n * stt - st * st;
    if (n < 3 || denom <= 0) return std::nullopt;
    return (n * sty - st * sy) / denom;
}

Significance significantDivergence(std::span<const double> d, std::span<const double> floor_a,
                                   std::span<const double> floor_b, std::span<const double> t) {
    Significance s;
    const std::size_t n = std::min({d.size(), floor_a.size(), floor_b.size(), t.size()});
    std::size_t count = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (d[i] > std::max(floor_a[i], floor_b[i])) {
            ++count;
            if (!s.first_time) s.first_time = t[i];
        }
    }
    s.fraction = n ? static_cast<double>(count) / static_cast<double>(n) : 0;
    return s;
}

}  // namespace vroc::harness
