// SPDX-License-Identifier: MIT
// The life of a harness command whose runs go through a RunPool (compare, check, sweep, ensemble),
// shared by the `vroc` program and the Python module: the output folder made ready, the pool, the
// command's document, and on rank 0 <out>/metrics.json and report.html.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include "vroc/harness/pool/run_pool.h"

namespace vroc::harness {

struct PooledCommand {
    std::filesystem::path out;     ///< the command's output folder; empty: no files at all (a library
                                   ///< caller: the runs' results come back over the workers' pipes)
    bool out_given = false;        ///< the user named `out` (needed by resume)
    int jobs = 0;                  ///< PoolOptions::jobs
    bool resume = false;           ///< PoolOptions::resume
    Json plan;                     ///< PoolOptions::plan
    std::string command = "vroc";  ///< for messages, e.g. "vroc sweep"
    std::function<void(const PoolProgress&)> progress;   ///< may be empty
};

/// What a pooled command produced: its document on every rank; on rank 0 also the report it wrote.
struct PooledOutput {
    Json doc;
    std::filesystem::path report;   ///< absolute; empty on ranks other than 0
};

/// The output folder of a pooled command, made ready on rank 0: created, and its earlier
/// metrics.json and report removed so it does not look complete while runs are redone. Resuming
/// needs the folder of the interrupted command. Throws InputError.
void prepareRunsOutput(const std::filesystem::path& out, bool resume, bool out_given);

/// Prepares `command.out`, makes the pool (finished runs to <out>/runs), runs `body` on it, and on
/// rank 0 writes <out>/metrics.json and report.html. With an empty `out`, only the document.
PooledOutput runPooledCommand(const PooledCommand& command, const std::function<Json(RunPool&)>& body);

}  // namespace vroc::harness
