// SPDX-License-Identifier: MIT
// Facts about this build, recorded in every run.json so a result can be traced to its binary.
#pragma once

#include <string>

namespace vroc {

struct BuildInfo {
    std::string version;    ///< project version, e.g. "0.1.0"
    std::string commit;     ///< short git commit at build time, "unknown" outside a clone
    std::string compiler;   ///< compiler id and version, e.g. "GNU 12.2.0"
    std::string flags;      ///< C++ flags of the build type (optimisation, -ffp-contract=off)
};

/// The facts of the build that compiled core (the commit as of the last build).
const BuildInfo& buildInfo();

}  // namespace vroc
