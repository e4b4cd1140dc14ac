// SPDX-License-Identifier: MIT
// `--jobs` and `--resume`, shared by the commands that run many independent runs (sweep, check,
// compare, ensemble), and the RunPool they configure (vroc/harness/run_pool.h).
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "progress_bar.h"
#include "vroc/harness/run_pool.h"

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

/// The output folder of a pooled command, made ready on rank 0: created, and its earlier
/// metrics.json and report removed so it does not look complete while runs are redone. --resume
/// needs the folder of the interrupted command (--out). Throws InputError.
void prepareRunsOutput(const std::filesystem::path& out, const PoolArgs& args, bool out_given);

/// A pool writing finished runs to <out>/runs, with a progress bar on a terminal (rank 0 only).
harness::RunPool makeRunPool(const PoolArgs& args, const std::filesystem::path& out, const harness::Json& plan,
                             const std::string& command, bool show_progress, std::shared_ptr<ProgressBar>& bar);

}  // namespace vroc::cli
