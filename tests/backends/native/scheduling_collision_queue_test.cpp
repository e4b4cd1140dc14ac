// SPDX-License-Identifier: MIT
// CollisionQueue against a brute-force model (a map pair -> current key, scanned for the minimum).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <tuple>
#include <vector>

#include "scheduling/collision_queue.h"

namespace vroc::native {
namespace {

struct ModelEntry {
    double time;
    int a, b;
};

// The reference: every live pair with its key; pop = minimum by (time, pair).
class Model {
public:
    void push(int pair, int a, int b, double t) { live_[pair] = {t, a, b}; }
    void invalidateBody(int body) {
        std::erase_if(live_, [body](const auto& kv) { return kv.second.a == body || kv.second.b == body; });
    }
    void removePair(int pair) { live_.erase(pair); }
    std::optional<QueueEntry> pop() {
        if (live_.empty()) return std::nullopt;
        auto best = live_.begin();
        for (auto it = live_.begin(); it != live_.end(); ++it) {
            if (std::tie(it->second.time, it->first) < std::tie(best->second.time, best->first)) best = it;
        }
        QueueEntry e{best->second.time, best->first, best->second.a, best->second.b};
        live_.erase(best);
        return e;
    }

private:
    std::map<int, ModelEntry> live_;
};

TEST(SchedulingCollisionQueue, PopsInTimeOrderWithTiesByPairIndex) {
    CollisionQueue q;
    std::mt19937_64 rng(5);
    std::uniform_int_distribution<int> coarse(0, 20);   // many equal times
    std::vector<std::pair<double, int>> expected;
    for (int pair = 0; pair < 500; ++pair) {
        const double t = 0.01 * coarse(rng);
        q.push(pair, pair % 37, 37 + pair % 11, t);
        expected.emplace_back(t, pair);
    }
    std::sort(expected.begin(), expected.end());
    for (const auto& [t, pair] : expected) {
        const auto e = q.pop();
        ASSERT_TRUE(e.has_value());
        EXPECT_EQ(e->time, t);
        EXPECT_EQ(e->pair, pair);
    }
    EXPECT_FALSE(q.pop().has_value());
    EXPECT_EQ(q.stats().pops, 500);
    EXPECT_EQ(q.stats().pushes, 500);
}

TEST(SchedulingCollisionQueue, InvalidationMatchesBruteForceModel) {
    std::mt19937_64 rng(6);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const int bodies = 30;
    // A fixed pair list over the bodies (pair index -> bodies), as the broad phase would give.
    std::vector<std::pair<int, int>> pairs;
    for (int a = 0; a < bodies; ++a)
        for (int b = a + 1; b < bodies; ++b)
            if (u(rng) < 0.2) pairs.emplace_back(a, b);
    CollisionQueue q;
    Model model;
    std::int64_t pops = 0;
    for (int step = 0; step < 50000; ++step) {
        const double op = u(rng);
        if (op < 0.5) {
            const int p = static_cast<int>(u(rng) * pairs.size());
            const double t = std::floor(u(rng) * 100) / 100;   // ties on purpose
            q.push(p, pairs[p].first, pairs[p].second, t);
            model.push(p, pairs[p].first, pairs[p].second, t);
        } else if (op < 0.65) {
            const int body = static_cast<int>(u(rng) * bodies);
            q.invalidateBody(body);
            model.invalidateBody(body);
        } else if (op < 0.7) {
            const int p = static_cast<int>(u(rng) * pairs.size());
            q.removePair(p);
            model.removePair(p);
        } else {
            const auto got = q.pop();
            const auto want = model.pop();
            ASSERT_EQ(got.has_value(), want.has_value()) << "step " << step;
            if (got) {
                ++pops;
                ASSERT_EQ(got->pair, want->pair) << "step " << step;
                ASSERT_EQ(got->time, want->time) << "step " << step;
                ASSERT_EQ(got->body_a, want->body_a);
                ASSERT_EQ(got->body_b, want->body_b);
            }
        }
    }
    EXPECT_EQ(q.stats().pops, pops);
    EXPECT_GT(q.stats().stale_pops, 0);
    EXPECT_GT(q.stats().compactions, 0);
    // Memory stays bounded by the compaction rule despite 25,000 pushes.
    EXPECT_LT(q.storedEntries(), 4 * pairs.size() + 64);
}

TEST(SchedulingCollisionQueue, SameEntriesInAnyOrderPopIdentically) {
    std::mt19937_64 rng(8);
    std::uniform_int_distribution<int> coarse(0, 9);
    struct Op { int pair, a, b; double t; };
    std::vector<Op> ops;
    for (int pair = 0; pair < 300; ++pair) ops.push_back({pair, pair % 17, 17 + pair % 5, 0.1 * coarse(rng)});
    std::vector<std::tuple<double, int, int, int>> reference;
    for (int perm = 0; perm < 20; ++perm) {
        std::shuffle(ops.begin(), ops.end(), rng);
        CollisionQueue q;
        for (const Op& o : ops) q.push(o.pair, o.a, o.b, o.t);
        q.invalidateBody(3);   // the same invalidation each time
        for (const Op& o : ops) if (o.a == 3) q.push(o.pair, o.a, o.b, o.t + 0.05);
        std::vector<std::tuple<double, int, int, int>> popped;
        while (auto e = q.pop()) popped.emplace_back(e->time, e->pair, e->body_a, e->body_b);
        ASSERT_EQ(popped.size(), ops.size());
        if (perm == 0) reference = popped;
        else ASSERT_EQ(popped, reference) << "permutation " << perm;
    }
}

TEST(SchedulingCollisionQueue, NanAndInfinityAreSafe) {
    CollisionQueue q;
    q.push(0, 0, 1, std::numeric_limits<double>::infinity());
    q.push(1, 1, 2, std::nan(""), 0.25);
    q.push(2, 2, 3, 0.5);
    EXPECT_EQ(q.stats().nan_times, 1);
    EXPECT_EQ(q.nextTime(), 0.25);
    EXPECT_EQ(q.pop()->pair, 1);
    EXPECT_EQ(q.pop()->pair, 2);
    EXPECT_EQ(q.pop()->pair, 0);
    EXPECT_TRUE(q.empty());
    EXPECT_EQ(q.nextTime(), std::numeric_limits<double>::infinity());
    // A re-pushed pair replaces its key; clear() drops everything.
    q.push(4, 0, 1, 1.0);
    q.push(4, 0, 1, 2.0);
    EXPECT_EQ(q.top()->time, 2.0);
    q.clear();
    EXPECT_TRUE(q.empty());
}

}  // namespace
}  // namespace vroc::native
