// SPDX-License-Identifier: MIT
// Heap allocations per internal step of the native backend once a scene has settled (issue 22,
// item 4: the target is zero). This binary replaces the global operator new with a counting one,
// which is why it is a suite of its own: the count covers everything the backend allocates
// between two frames, seen from outside (no backend hook).
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <string>

#include <gtest/gtest.h>

#include "../native_test_scenes.h"
#include "vroc/core/scene_loader.h"

namespace {

std::atomic<bool> g_counting{false};
std::atomic<std::uint64_t> g_allocations{0};

void* countedAllocation(std::size_t size) {
    if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1, std::memory_order_relaxed);
    if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}

void* countedAlignedAllocation(std::size_t size, std::align_val_t align) {
    if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1, std::memory_order_relaxed);
    const auto a = static_cast<std::size_t>(align);
    if (void* p = std::aligned_alloc(a, (size + a - 1) / a * a)) return p;
    throw std::bad_alloc();
}

}  // namespace

void* operator new(std::size_t size) { return countedAllocation(size); }
void* operator new[](std::size_t size) { return countedAllocation(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
    try {
        return countedAllocation(size);
    } catch (...) {
        return nullptr;
    }
}
void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept { return operator new(size, tag); }
void* operator new(std::size_t size, std::align_val_t align) { return countedAlignedAllocation(size, align); }
void* operator new[](std::size_t size, std::align_val_t align) { return countedAlignedAllocation(size, align); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }

namespace vroc::native::test {
namespace {

struct StepAllocations {
    std::uint64_t allocations = 0;
    double internal_steps = 0;
    double perStep() const { return internal_steps > 0 ? static_cast<double>(allocations) / internal_steps : 0.0; }
};

/// Steps `settle` frames uncounted, then counts the heap allocations of the next `frames` frames.
StepAllocations countAfterSettling(const std::string& scene_file, int settle, int frames,
                                   const NativeSettings& settings) {
    const Scene s = loadScene(std::string(VROC_SOURCE_DIR) + "/scenes/" + scene_file);
    auto be = makeBackend(s, settings);
    for (int f = 0; f < settle; ++f) be->stepFrame(s.frame_dt);
    const double steps_before = be->statistics().at("internal_steps");
    g_allocations = 0;
    g_counting = true;
    for (int f = 0; f < frames; ++f) be->stepFrame(s.frame_dt);
    g_counting = false;
    StepAllocations out;
    out.allocations = g_allocations;
    out.internal_steps = be->statistics().at("internal_steps") - steps_before;
    return out;
}

TEST(NativeStepAllocations, CountingOperatorNewSeesAnAllocation) {
    // The counter itself: a test that could not see an allocation could not fail.
    g_allocations = 0;
    g_counting = true;
    auto* p = new std::string(64, 'x');
    g_counting = false;
    delete p;
    EXPECT_GE(g_allocations.load(), 1u);
}

// Issue 22's target: no heap allocation in an internal step once a scene has settled. The step's
// buffers (contact patch, manifolds, pair samples, island solves, solver arrays, broad-phase
// merges) keep their storage from step to step. History (settled pyramid10): 10,514 allocations
// per internal step before, 0 after.
void expectNoAllocationOnceSettled(const char* scene, int settle, int threads,
                                   TouchingRegime touching = TouchingRegime::Protected) {
    NativeSettings settings;
    settings.threads = threads;
    settings.touching = touching;
    const StepAllocations a = countAfterSettling(scene, settle, 60, settings);
    std::printf("settled %s, %d worker(s), touching %d: %llu allocations over %.0f internal steps\n", scene, threads,
                static_cast<int>(touching), static_cast<unsigned long long>(a.allocations), a.internal_steps);
    ASSERT_GT(a.internal_steps, 0.0);
    EXPECT_EQ(a.allocations, 0u) << a.perStep() << " per internal step";
}

TEST(NativeStepAllocations, SettledPyramidStepsAllocateNothing) {
    // A base-10 pyramid: settled after 1 s, then 1 s counted.
    expectNoAllocationOnceSettled("stress/pyramid10.json", 60, 1);
}

TEST(NativeStepAllocations, SettledBinOfBoxesStepsAllocateNothing) {
    // 100 random boxes dropped into a bin: settled after 5 s (the last box stops moving between 3
    // and 3.5 s: shock levels that follow gravity, 2026-12-06), then 1 s counted; with one worker
    // and with two (the narrow phase and the islands then run on the pool's threads).
    expectNoAllocationOnceSettled("stress/bin_boxes100.json", 300, 1);
    expectNoAllocationOnceSettled("stress/bin_boxes100.json", 300, 2);
}

TEST(NativeStepAllocations, SettledScenesOnFixedTicksAllocateNothing) {
    // The fixed-tick regime (native.touching=fixed) keeps the same buffers, and its impact passes
    // their own (island_scratch_.impact, kicked): a settled pyramid and bin, one and two workers.
    expectNoAllocationOnceSettled("stress/pyramid10.json", 60, 1, TouchingRegime::Fixed);
    expectNoAllocationOnceSettled("stress/bin_boxes100.json", 180, 1, TouchingRegime::Fixed);
    expectNoAllocationOnceSettled("stress/bin_boxes100.json", 180, 2, TouchingRegime::Fixed);
}

}  // namespace
}  // namespace vroc::native::test
