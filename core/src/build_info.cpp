// SPDX-License-Identifier: MIT
#include "vroc/core/build_info.h"

// CMake passes these for vroc_core (core/CMakeLists.txt, cmake/BuildInfo.cmake); the commit comes
// from a header the build writes at every build (cmake/WriteBuildCommit.cmake). The fallbacks
// keep the file compiling if someone builds it by hand.
#if __has_include("vroc_build_commit.h")
#include "vroc_build_commit.h"
#endif
#ifndef VROC_VERSION
#define VROC_VERSION "unknown"
#endif
#ifndef VROC_GIT_COMMIT
#define VROC_GIT_COMMIT "unknown"
#endif
#ifndef VROC_COMPILER
#define VROC_COMPILER "unknown"
#endif
#ifndef VROC_BUILD_FLAGS
#define VROC_BUILD_FLAGS ""
#endif

namespace vroc {

const BuildInfo& buildInfo() {
    static const BuildInfo info{VROC_VERSION, VROC_GIT_COMMIT, VROC_COMPILER, VROC_BUILD_FLAGS};
    return info;
}

}  // namespace vroc
