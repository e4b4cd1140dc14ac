// SPDX-License-Identifier: MIT
#include "vroc/harness/statistics/two_sample_tests.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace vroc::harness {
namespace {

double distance(const Sample& a, const Sample& b) {
    double s = 0;
    for (std::size_t k = 0; k < a.size(); ++k) s += (a[k] - b[k]) * (a[k] - b[k]);
    return std::sqrt(s);
}

// Energy distance from the pooled distance matrix and a labelling (true = first sample).
double energyFromMatrix(const std::vector<double>& d, std::size_t n, const std::vector<char>& first) {
    double xy = 0, xx = 0, yy = 0;
    std::size_t nx = 0;
    for (char f : first) nx += f ? 1 : 0;
    const std::size_t ny = n - nx;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j) {
            const double v = d[i * n + j];
            if (first[i] && first[j]) xx += v;
            else if (!first[i] && !first[j]) yy += v;
            else xy += v;
        }
    // Unordered pairs: the within means over i != j are xx / (nx (nx - 1) / 2), and so on.
    return 2 * xy / (double(nx) * double(ny)) - 2 * xx / (double(nx) * double(nx - 1)) -
           2 * yy / (double(ny) * double(ny - 1));
}

}  // namespace

std::uint64_t SplitMix64::next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

double SplitMix64::uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

double SplitMix64::normal() {
    const double u1 = 1.0 - uniform();   // (0, 1]
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
}

double energyDistance(const std::vector<Sample>& x, const std::vector<Sample>& y) {
    if (x.size() < 2 || y.size() < 2)
        throw std::invalid_argument("energyDistance: a sample has fewer than 2 observations");
    double xy = 0, xx = 0, yy = 0;
    for (const Sample& a : x)
        for (const Sample& b : y) xy += distance(a, b);
    for (std::size_t i = 0; i < x.size(); ++i)
        for (std::size_t j = i + 1; j < x.size(); ++j) xx += distance(x[i], x[j]);
    for (std::size_t i = 0; i < y.size(); ++i)
        for (std::size_t j = i + 1; j < y.size(); ++j) yy += distance(y[i], y[j]);
    const double n = double(x.size()), m = double(y.size());
    // Not clamped at 0: a clamp would bring back a positive bias.
    return 2 * xy / (n * m) - 2 * xx / (n * (n - 1)) - 2 * yy / (m * (m - 1));
}

double marginalWasserstein1(const std::vector<Sample>& x, const std::vector<Sample>& y) {
    if (x.empty() || y.empty()) throw std::invalid_argument("marginalWasserstein1: empty sample");
    double sum = 0;
    for (std::size_t k = 0; k < x.front().size(); ++k) {
        std::vector<double> xk, yk;
        for (const Sample& s : x) xk.push_back(s[k]);
        for (const Sample& s : y) yk.push_back(s[k]);
        const double w = wasserstein1(std::move(xk), std::move(yk));
        sum += w * w;
    }
    return std::sqrt(sum);
}

double wasserstein1(std::vector<double> x, std::vector<double> y) {
    if (x.empty() || y.empty()) throw std::invalid_argument("wasserstein1: empty sample");
    std::sort(x.begin(), x.end());
    std::sort(y.begin(), y.end());
    // Integrate |F - G| over the merged breakpoints.
    std::vector<double> all = x;
    all.insert(all.end(), y.begin(), y.end());
    std::sort(all.begin(), all.end());
    double w = 0;
    std::size_t i = 0, j = 0;
    for (std::size_t k = 0; k + 1 < all.size(); ++k) {
        while (i < x.size() && x[i] <= all[k]) ++i;
        while (j < y.size() && y[j] <= all[k]) ++j;
        const double f = double(i) / double(x.size()), g = double(j) / double(y.size());
        w += std::abs(f - g) * (all[k + 1] - all[k]);
    }
    return w;
}

PermutationTest energyPermutationTest(const std::vector<Sample>& x, const std::vector<Sample>& y, int permutations,
                                      std::uint64_t seed) {
    if (x.size() < 2 || y.size() < 2)
        throw std::invalid_argument("energyPermutationTest: a sample has fewer than 2 observations");
    const std::size_t n = x.size() + y.size();
    std::vector<const Sample*> pooled;
    for (const Sample& s : x) pooled.push_back(&s);
    for (const Sample& s : y) pooled.push_back(&s);
    std::vector<double> d(n * n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j) d[i * n + j] = distance(*pooled[i], *pooled[j]);
    std::vector<char> first(n, 0);
    std::fill(first.begin(), first.begin() + static_cast<std::ptrdiff_t>(x.size()), 1);
    PermutationTest t;
    t.statistic = energyFromMatrix(d, n, first);
    t.permutations = permutations;
    SplitMix64 rng(seed);
    int as_large = 0;
    // Ties (e.g. a deterministic observable, all equal) count as "as large": p stays 1.
    const double tolerance = 1e-12 * std::max(1.0, std::abs(t.statistic));
    for (int p = 0; p < permutations; ++p) {
        for (std::size_t i = n - 1; i > 0; --i) std::swap(first[i], first[rng.next() % (i + 1)]);
        if (energyFromMatrix(d, n, first) >= t.statistic - tolerance) ++as_large;
    }
    t.p_value = (1.0 + as_large) / (1.0 + permutations);
    return t;
}

PairedTest pairedSignFlipTest(const std::vector<double>& a, const std::vector<double>& b, int permutations,
                              std::uint64_t seed) {
    if (a.size() != b.size() || a.empty())
        throw std::invalid_argument("pairedSignFlipTest: expected equal, non-empty samples");
    std::vector<double> d(a.size());
    for (std::size_t k = 0; k < a.size(); ++k) d[k] = a[k] - b[k];
    const double n = double(d.size());
    PairedTest t;
    t.pairs = d.size();
    t.mean_difference = std::accumulate(d.begin(), d.end(), 0.0) / n;
    t.permutations = permutations;
    const double observed = std::abs(t.mean_difference);
    // Ties count as "as large" (all differences 0: p = 1); the tolerance absorbs summation order.
    double scale = 0;
    for (double v : d) scale += std::abs(v) / n;
    const double tolerance = 1e-12 * std::max(1.0, scale);
    SplitMix64 rng(seed);
    int as_large = 0;
    for (int p = 0; p < permutations; ++p) {
        double sum = 0;
        std::uint64_t bits = 0;
        for (std::size_t k = 0; k < d.size(); ++k) {
            if (k % 64 == 0) bits = rng.next();
            sum += (bits & 1) ? d[k] : -d[k];
            bits >>= 1;
        }
        if (std::abs(sum / n) >= observed - tolerance) ++as_large;
    }
    t.p_value = (1.0 + as_large) / (1.0 + permutations);
    return t;
}

std::vector<double> holmAdjusted(const std::vector<double>& p) {
    const std::size_t k = p.size();
    std::vector<std::size_t> order(k);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p[a] < p[b]; });
    std::vector<double> out(k);
    double running = 0;
    for (std::size_t r = 0; r < k; ++r) {
        running = std::max(running, std::min(1.0, double(k - r) * p[order[r]]));
        out[order[r]] = running;
    }
    return out;
}

}  // namespace vroc::harness
