// SPDX-License-Identifier: MIT
// `--jobs` and `--resume`, shared by the commands that run many independent runs (sweep, check,
// compare, ensemble), and the RunPool they configure (vroc/harness/pool/run_pool.h).
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "progress_bar.h"
#include "vroc/harness/pool/run_pool.h"

namespace CLI {
class App;
}

namespace vroc::cli {

struct PoolArgs {
    int jobs = 0;          ///< 0: every core (one per rank under mpirun)
    bool resume = false;
};

/// Declares --jobs/-j and --resume on `sub`.
void addPoolOptions(CLI::App& sub, PoolArgs& args);

/// What a pooled command produced: its document on every rank; on rank 0 also the report it wrote.
struct PooledResult {
    harness::Json doc;
    std::filesystem::path report;   ///< absolute; empty on ranks other than 0
};

/// The life of a pooled command: prepares `out`, makes the pool (finished runs to <out>/runs, a
/// progress bar on a terminal), runs `body` on it, and on rank 0 writes <out>/metrics.json and
/// report.html. `out_given`: --out was on the command line (needed by --resume).
PooledResult runPooled(const PoolArgs& args, const std::filesystem::path& out, bool out_given, const harness::Json& plan,
                       const std::string& command, bool show_progress,
                       const std::function<harness::Json(harness::RunPool&)>& body);

}  // namespace vroc::cli
