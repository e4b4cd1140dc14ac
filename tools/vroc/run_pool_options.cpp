// SPDX-License-Identifier: MIT
#include "run_pool_options.h"

#include <CLI/CLI.hpp>

#include "vroc/harness/commands/pooled_command.h"
#include "vroc/harness/pool/mpi_world.h"

namespace vroc::cli {

void addPoolOptions(CLI::App& sub, PoolArgs& a) {
    sub.add_option("--jobs,-j", a.jobs, "Runs at once, in that many worker processes (default: every core; under mpirun: one per rank)")
        ->check(CLI::NonNegativeNumber);
    sub.add_flag("--resume", a.resume, "Keep the finished runs in --out of an interrupted command and run only the missing ones");
}

PooledResult runPooled(const PoolArgs& a, const std::filesystem::path& out, bool out_given, const harness::Json& plan,
                       const std::string& command, bool show_progress,
                       const std::function<harness::Json(harness::RunPool&)>& body) {
    harness::PooledCommand c;
    c.out = out;
    c.out_given = out_given;
    c.jobs = a.jobs;
    c.resume = a.resume;
    c.plan = plan;
    c.command = "vroc " + command;
    auto bar = std::make_shared<ProgressBar>(show_progress && harness::mpi::isRoot(), "vroc " + command);
    c.progress = [bar](const harness::PoolProgress& p) { bar->updateRuns(p.done, p.failed, p.total, p.seconds_left); };
    harness::PooledOutput r = harness::runPooledCommand(c, body);
    bar->finish();
    return {std::move(r.doc), std::move(r.report)};
}

}  // namespace vroc::cli
