// SPDX-License-Identifier: MIT
// SpinBarrier: the workers of one island's sweeps meet here after every colour group, a few
// microseconds apart; a futex-based barrier (std::barrier) would put each to sleep and back at
// every group. Spins, then yields, so an oversubscribed machine still makes progress.
#pragma once

#include <atomic>
#include <cstdint>
#include <thread>

namespace vroc::native {

class SpinBarrier {
public:
    explicit SpinBarrier(int count) : count_(count) {}

    /// Returns once all `count` threads have called it (for this generation). Writes made before
    /// the call by any thread are visible to every thread after it.
    void arriveAndWait() {
        const std::uint32_t generation = generation_.load(std::memory_order_acquire);
        if (arrived_.fetch_add(1, std::memory_order_acq_rel) + 1 == count_) {
            arrived_.store(0, std::memory_order_relaxed);
            generation_.fetch_add(1, std::memory_order_acq_rel);
            return;
        }
        for (int spins = 0; generation_.load(std::memory_order_acquire) == generation; ++spins) {
            if (spins < kSpins) {
#if defined(__x86_64__) || defined(__i386__)
                __builtin_ia32_pause();
#endif
            } else {
                std::this_thread::yield();
            }
        }
    }

private:
    static constexpr int kSpins = 1 << 14;
    const int count_;
    std::atomic<int> arrived_{0};
    std::atomic<std::uint32_t> generation_{0};
};

}  // namespace vroc::native
