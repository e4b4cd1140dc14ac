// SPDX-License-Identifier: MIT
// PairPartition: round-robin ownership, and merged results bit-identical for 1, 2, 3 and 4 workers.
#include <gtest/gtest.h>

#include <atomic>
#include <cstring>
#include <random>
#include <stdexcept>
#include <vector>

#include "scheduling/collision_time_bound.h"
#include "scheduling/pair_partition.h"

namespace vroc::native {
namespace {

struct PairInput {
    double gap;
    Vec3 normal;
    MotionBound a, b;
};

std::vector<PairInput> randomPairs(int count) {
    std::mt19937_64 rng(21);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<PairInput> pairs;
    for (int i = 0; i < count; ++i) {
        PairInput p;
        p.gap = 0.5 * (1.0 + u(rng));
        p.normal = Vec3(u(rng), u(rng), u(rng)).normalized();
        p.a = {Vec3(u(rng), u(rng), u(rng)) * 5.0, Vec3(0, 0, -9.81), 10.0 * (1 + u(rng)), 0.3, 0.1};
        p.b = {Vec3(u(rng), u(rng), u(rng)) * 5.0, Vec3(0, 0, -9.81), 10.0 * (1 + u(rng)), 0.5, 0.05};
        pairs.push_back(p);
    }
    return pairs;
}

struct Event {
    double time;
    int pair;
};

TEST(SchedulingPairPartition, RoundRobinOwnershipEachPairOnce) {
    for (int workers : {1, 2, 3, 4}) {
        PairPartition partition(workers);
        const std::size_t count = 1001;
        std::vector<int> owner(count, -1);
        std::vector<std::atomic<int>> calls(count);
        partition.run(count, [&](std::size_t i, int w) {
            owner[i] = w;
            calls[i].fetch_add(1);
        });
        for (std::size_t i = 0; i < count; ++i) {
            ASSERT_EQ(calls[i].load(), 1) << "pair " << i << " workers " << workers;
            ASSERT_EQ(owner[i], PairPartition::ownerOf(i, workers));
            ASSERT_EQ(owner[i], static_cast<int>(i % workers));
        }
    }
}

TEST(SchedulingPairPartition, MergedResultsBitIdenticalForAnyWorkerCount) {
    const auto pairs = randomPairs(5000);
    const double frame = 1.0 / 60.0;
    auto earliest = [&](std::size_t i) {
        const PairInput& p = pairs[i];
        return earliestCollisionTime(p.gap, p.normal, p.a, p.b, 10 * frame);
    };
    auto events = [&](std::size_t i, std::vector<Event>& out) {
        const double t = earliest(i);
        if (t <= frame) out.push_back({t, static_cast<int>(i)});
    };
    auto by_time_then_pair = [](const Event& x, const Event& y) {
        return x.time != y.time ? x.time < y.time : x.pair < y.pair;
    };
    std::vector<double> reference_times;
    std::vector<Event> reference_events;
    for (int workers : {1, 2, 3, 4}) {
        PairPartition partition(workers);
        for (int repeat = 0; repeat < 20; ++repeat) {   // the pool is reused between runs
            const auto times = partition.map<double>(pairs.size(), earliest);
            const auto merged = partition.collect<Event>(pairs.size(), events, by_time_then_pair);
            if (reference_times.empty()) {
                reference_times = times;
                reference_events = merged;
                ASSERT_GT(merged.size(), 100u);
                ASSERT_LT(merged.size(), pairs.size());
                continue;
            }
            ASSERT_EQ(std::memcmp(times.data(), reference_times.data(), times.size() * sizeof(double)), 0)
                << workers << " workers";
            ASSERT_EQ(merged.size(), reference_events.size());
            for (std::size_t k = 0; k < merged.size(); ++k) {
                ASSERT_EQ(std::memcmp(&merged[k].time, &reference_events[k].time, sizeof(double)), 0);
                ASSERT_EQ(merged[k].pair, reference_events[k].pair);
            }
        }
    }
    // Independent check of the serial answer: the merged events are exactly the pairs whose
    // bound falls within the frame, in (time, pair) order.
    std::vector<Event> direct;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        const double t = earliest(i);
        if (t <= frame) direct.push_back({t, static_cast<int>(i)});
    }
    std::sort(direct.begin(), direct.end(), by_time_then_pair);
    ASSERT_EQ(direct.size(), reference_events.size());
    for (std::size_t k = 0; k < direct.size(); ++k) EXPECT_EQ(direct[k].pair, reference_events[k].pair);
}

TEST(SchedulingPairPartition, ExceptionFromAWorkerReachesTheCaller) {
    PairPartition partition(3);
    EXPECT_THROW(partition.run(100, [](std::size_t i, int) {
        if (i == 41) throw std::runtime_error("pair 41");
    }), std::runtime_error);
    // The pool still works afterwards.
    std::atomic<int> n{0};
    partition.run(100, [&](std::size_t, int) { n.fetch_add(1); });
    EXPECT_EQ(n.load(), 100);
}

}  // namespace
}  // namespace vroc::native
