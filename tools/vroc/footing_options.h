// SPDX-License-Identifier: MIT
// `--footing` and `--footing-substeps`, shared by the commands that put engines side by side
// (check, compare, sweep, ensemble): on what footing the engines run (vroc/harness/backend_selection.h).
#pragma once

#include <string>
#include <vector>

#include "vroc/harness/backend_selection.h"

namespace CLI {
class App;
}

namespace vroc::cli {

struct FootingArgs {
    std::string kind = "defaults";   ///< "defaults" or "equal"
    int substeps = 4;                ///< [steps per frame] on the equal footing
};

/// Declares --footing and --footing-substeps on `sub`.
void addFootingOptions(CLI::App& sub, FootingArgs& args);

/// The footing the options ask for; throws InputError for a word that is not one.
harness::Footing footingOf(const FootingArgs& args);

/// On the equal footing, "vroc <command>: footing ..." on stderr (rank 0, unless `quiet`); the
/// defaults footing is the normal case and says nothing.
void announceFooting(const std::string& command, const std::vector<harness::SelectedBackend>& backends, bool quiet);

}  // namespace vroc::cli
