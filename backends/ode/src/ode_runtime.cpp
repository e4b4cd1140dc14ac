// SPDX-License-Identifier: MIT
#include "ode_runtime.h"

#include <cstdarg>
#include <cstdio>
#include <mutex>

namespace vroc::ode {
namespace {

thread_local OdeMessageCounts* t_capture = nullptr;

void countMessage(int errnum, const char* msg, va_list ap) {
    if (t_capture) {
        ++(errnum == d_ERR_LCP ? t_capture->lcp : t_capture->other);
        return;
    }
    std::fprintf(stderr, "ODE Message %d: ", errnum);
    std::vfprintf(stderr, msg, ap);
    std::fprintf(stderr, "\n");
}

}  // namespace

MessageCapture::MessageCapture(OdeMessageCounts& counts) : previous_(t_capture) { t_capture = &counts; }
MessageCapture::~MessageCapture() { t_capture = previous_; }

void ensureOdeReady() {
    static std::once_flag once;
    std::call_once(once, [] {
        dInitODE2(0);
        dSetMessageHandler(&countMessage);
    });
    // ODE's collision functions need per-thread data; allocating twice is a no-op, but the
    // flag saves the library call on every frame.
    thread_local bool thread_ready = false;
    if (!thread_ready) thread_ready = dAllocateODEDataForThread(dAllocateMaskAll) != 0;
}

bool seededWorldStep(dWorldID world, Stepper stepper, double h, unsigned long& seed) {
    static std::mutex generator_mutex;
    std::lock_guard<std::mutex> lock(generator_mutex);
    dRandSetSeed(seed);
    const int ok = stepper == Stepper::QuickStep ? dWorldQuickStep(world, h) : dWorldStep(world, h);
    seed = dRandGetSeed();
    return ok != 0;
}

}  // namespace vroc::ode
