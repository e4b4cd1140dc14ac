// SPDX-License-Identifier: MIT
// `--footing` and `--footing-substeps`, shared by the commands that put engines side by side
// (check, compare, sweep, ensemble): on what footing the engines run (vroc/harness/runs/backend_selection.h);
// check and compare also run both footings side by side (`--footing both`).
#pragma once

#include <string>
#include <vector>

#include "vroc/harness/runs/backend_selection.h"

namespace CLI {
class App;
}

namespace vroc::cli {

struct FootingArgs {
    std::string kind = "defaults";   ///< "defaults", "equal" or (check, compare) "both"
    int substeps = 4;                ///< [steps per frame] on the equal footing
};

/// Declares --footing and --footing-substeps on `sub`.
void addFootingOptions(CLI::App& sub, FootingArgs& args);

/// The backends of `list` on the footing the options ask for (harness::selectBackendsOnFooting);
/// with "both" (`both_allowed`: check and compare), every backend twice, own defaults then equal
/// footing. Throws InputError for a word that is not a footing, and for "both" in sweep and ensemble.
std::vector<harness::SelectedBackend> footedBackends(const FootingArgs& args, const std::string& list,
                                                     const std::vector<std::string>& assignments, bool both_allowed);

/// On the equal footing or both, "vroc <command>: footing ..." on stderr (rank 0, unless `quiet`);
/// the defaults footing is the normal case and says nothing.
void announceFooting(const std::string& command, const std::vector<harness::SelectedBackend>& backends, bool quiet);

}  // namespace vroc::cli
