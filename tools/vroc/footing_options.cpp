// SPDX-License-Identifier: MIT
#include "footing_options.h"

#include <CLI/CLI.hpp>

#include "vroc/harness/mpi_world.h"

namespace vroc::cli {

void addFootingOptions(CLI::App& sub, FootingArgs& args) {
    sub.add_option("--footing", args.kind,
                   "defaults: each engine at its own defaults, every departure listed (the default); equal: the "
                   "same internal steps per frame on every engine and isotropic Coulomb friction where it has it "
                   "(docs/harness.md, \"Footing\"); --set still wins");
    sub.add_option("--footing-substeps", args.substeps, "Internal steps per frame on the equal footing (default 4)");
}

harness::Footing footingOf(const FootingArgs& args) {
    harness::Footing f;
    f.kind = harness::footingKind(args.kind);
    f.substeps = args.substeps;
    return f;
}

void announceFooting(const std::string& command, const std::vector<harness::SelectedBackend>& backends, bool quiet) {
    if (quiet || !harness::mpi::isRoot() || backends.empty()) return;
    if (backends.front().footing.kind != harness::Footing::Kind::Equal) return;
    harness::progressLine(command, "footing " + harness::footingText(backends.front().footing));
}

}  // namespace vroc::cli
