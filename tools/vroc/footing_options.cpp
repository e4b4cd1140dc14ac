// SPDX-License-Identifier: MIT
#include "footing_options.h"

#include <CLI/CLI.hpp>

#include "vroc/harness/pool/mpi_world.h"

namespace vroc::cli {

void addFootingOptions(CLI::App& sub, FootingArgs& args) {
    sub.add_option("--footing", args.kind,
                   "defaults: each engine at its own defaults, every departure listed (the default); equal: the "
                   "same internal steps per frame on every engine and isotropic Coulomb friction where it has it "
                   "(docs/harness.md, \"Footing\"); --set still wins. check and compare also take both: every "
                   "engine on each footing, side by side in one report");
    sub.add_option("--footing-substeps", args.substeps, "Internal steps per frame on the equal footing (default 4)");
}

std::vector<harness::SelectedBackend> footedBackends(const FootingArgs& args, const std::string& list,
                                                     const std::vector<std::string>& assignments, bool both_allowed) {
    return harness::selectBackendsOnFooting(list, assignments, args.kind, args.substeps, both_allowed);
}

void announceFooting(const std::string& command, const std::vector<harness::SelectedBackend>& backends, bool quiet) {
    if (quiet || !harness::mpi::isRoot() || backends.empty()) return;
    if (backends.front().both_footings) {
        for (const harness::SelectedBackend& b : backends)
            if (b.footing.kind == harness::Footing::Kind::Equal)
                return harness::progressLine(command,
                                             "footing both, side by side: each backend at its own defaults and on " +
                                                 harness::footingText(b.footing));
    }
    if (backends.front().footing.kind != harness::Footing::Kind::Equal) return;
    harness::progressLine(command, "footing " + harness::footingText(backends.front().footing));
}

}  // namespace vroc::cli
