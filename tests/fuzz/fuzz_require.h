// SPDX-License-Identifier: MIT
// How a fuzz target states its contract: a violated requirement prints what was violated and
// traps, which libFuzzer reports as a crash and saves the input (a plain assert would vanish
// under NDEBUG, and an exception could be swallowed by the code under test).
#pragma once

#include <cstdio>

namespace vroc::fuzz {

[[noreturn]] inline void contractViolated(const char* what, const char* file, int line) {
    std::fprintf(stderr, "vroc fuzz: contract violated at %s:%d: %s\n", file, line, what);
    std::fflush(stderr);
    __builtin_trap();
}

}  // namespace vroc::fuzz

/// Requires `condition`; on failure names the condition and traps.
#define VROC_FUZZ_REQUIRE(condition) \
    ((condition) ? (void)0 : ::vroc::fuzz::contractViolated(#condition, __FILE__, __LINE__))
