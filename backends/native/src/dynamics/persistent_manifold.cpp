// SPDX-License-Identifier: MIT
#include "dynamics/persistent_manifold.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace vroc::native {

std::vector<Vec3> reduceContactPoints(const std::vector<Vec3>& points, const Vec3& normal) {
    std::vector<Vec3> out;
    for (std::size_t i : reduceContactPointIndices(points, normal)) out.push_back(points[i]);
    return out;
}

InlineVector<std::size_t, kMaxManifoldPoints> reduceContactPointIndices(std::span<const Vec3> points,
                                                                        const Vec3& normal,
                                                                        std::span<const double> gaps) {
    const std::size_t n = points.size();
    if (n <= kMaxManifoldPoints) {
        InlineVector<std::size_t, kMaxManifoldPoints> all;
        for (std::size_t i = 0; i < n; ++i) all.push_back(i);
        return all;
    }
    Vec3 centroid = Vec3::Zero();
    for (const Vec3& p : points) centroid += p;
    centroid /= static_cast<double>(n);
    auto argmax = [&](auto score) {
        std::size_t best = 0;
        double best_score = -std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < n; ++i) {
            const double s = score(i);
            if (s > best_score) {
                best_score = s;
                best = i;
            }
        }
        return best;
    };
    const std::size_t i0 = gaps.size() == n ? argmax([&](std::size_t i) { return -gaps[i]; })
                                            : argmax([&](std::size_t i) { return (points[i] - centroid).squaredNorm(); });
    const std::size_t i1 = argmax([&](std::size_t i) { return (points[i] - points[i0]).squaredNorm(); });
    auto area = [&](std::size_t x, std::size_t y, std::size_t z) {   // signed, about the normal
        return (points[y] - points[x]).cross(points[z] - points[x]).dot(normal);
    };
    const std::size_t i2 = argmax([&](std::size_t i) { return std::abs(area(i0, i1, i)); });
    const double side = area(i0, i1, i2) >= 0.0 ? 1.0 : -1.0;
    // The fourth point adds the most area outside the triangle (beyond any of its edges).
    const std::size_t i3 = argmax([&](std::size_t i) {
        if (i == i0 || i == i1 || i == i2) return -1.0;
        return std::max({-side * area(i0, i1, i), -side * area(i1, i2, i), -side * area(i2, i0, i)});
    });
    std::array<std::size_t, kMaxManifoldPoints> chosen{i0, i1, i2, i3};
    std::sort(chosen.begin(), chosen.end());
    InlineVector<std::size_t, kMaxManifoldPoints> keep;
    for (std::size_t k = 0; k < chosen.size(); ++k)
        if (k == 0 || chosen[k] != chosen[k - 1]) keep.push_back(chosen[k]);
    return keep;
}

namespace {

// Largest factor a warm start's impulses are scaled up by (a step 3x its cache's: the grid's 1.5 / 0.5).
constexpr double kMaxWarmScale = 3.0;

}  // namespace

void warmStartManifold(const PersistentManifold& cache, const Pose& frame_a, double step,
                       double match_radius, ContactManifold& m) {
    m.point_impulse.assign(m.points.size(), 0.0);
    m.tangent_impulse = Vec3::Zero();
    m.torsion_impulse = 0.0;
    if (cache.empty() || !(step > 0.0)) return;
    // A resting load's impulse grows with the step (m g h). Island ticks end on the sub-step grid,
    // so a tick after an off-grid solve is 0.5 to 1.5 sub-steps long and the next is a whole one:
    // the impulse follows the step, or a resting pile restarts below its load after every short
    // tick and jitters. Scaling up is capped at kMaxWarmScale: an impulse solved over a much shorter
    // step (a protection tick) may hold an impact's share, and a too-large start is what
    // Gauss-Seidel undoes worst.
    const double scale = std::min(kMaxWarmScale, step / cache.step);
    const double r2 = match_radius * match_radius;
    const Pose to_a = frame_a.inverse();
    // Cached points already matched, one bit each (a cache holds at most a manifold's eight).
    const std::size_t cached = std::min<std::size_t>(cache.local_a.size(), 64);
    std::uint64_t used = 0;
    int matched = 0;
    for (std::size_t i = 0; i < m.points.size(); ++i) {
        const Vec3 local = to_a.apply(m.points[i]);
        std::size_t best = cached;
        double best_d2 = r2;
        for (std::size_t k = 0; k < cached; ++k) {
            const double d2 = (cache.local_a[k] - local).squaredNorm();
            if ((used >> k & 1U) == 0 && d2 <= best_d2) {
                best_d2 = d2;
                best = k;
            }
        }
        if (best == cached) continue;
        used |= std::uint64_t{1} << best;
        ++matched;
        m.point_impulse[i] = scale * cache.normal_impulse[best];
    }
    if (matched == 0) return;
    m.tangent_impulse = scale * cache.tangent_impulse;
    m.torsion_impulse = scale * cache.torsion_impulse;
}

void storeManifold(PersistentManifold& cache, const Pose& frame_a, double step, const ContactManifold& m) {
    cache.clear();
    if (!(step > 0.0) || m.point_impulse.size() != m.points.size()) return;
    const Pose to_a = frame_a.inverse();
    for (std::size_t i = 0; i < m.points.size(); ++i) {
        cache.local_a.push_back(to_a.apply(m.points[i]));
        cache.normal_impulse.push_back(m.point_impulse[i]);
    }
    cache.tangent_impulse = m.tangent_impulse;
    cache.torsion_impulse = m.torsion_impulse;
    cache.step = step;
}

}  // namespace vroc::native
