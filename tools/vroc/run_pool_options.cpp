// SPDX-License-Identifier: MIT
#include "run_pool_options.h"

#include <CLI/CLI.hpp>

#include "vroc/core/errors.h"
#include "vroc/core/recording/atomic_output.h"
#include "vroc/harness/html_report.h"
#include "vroc/harness/mpi_world.h"

namespace vroc::cli {

void addPoolOptions(CLI::App& sub, PoolArgs& a) {
    sub.add_option("--jobs,-j", a.jobs, "Runs at once, in that many worker processes (default: every core; under mpirun: one per rank)")
        ->check(CLI::NonNegativeNumber);
    sub.add_flag("--resume", a.resume, "Keep the finished runs in --out of an interrupted command and run only the missing ones");
}

void prepareRunsOutput(const std::filesystem::path& out, const PoolArgs& a, bool out_given) {
    if (a.resume && !out_given) throw InputError("--resume: give --out, the output folder of the interrupted command");
    if (a.resume && !std::filesystem::is_directory(out / "runs"))
        throw InputError("--resume: " + (out / "runs").string() + " does not exist (nothing to resume; run without --resume)");
    if (!harness::mpi::isRoot()) return;
    recording::prepareOutputDirectory(out);
    std::error_code ec;
    for (const char* f : {"metrics.json", "report.html"}) std::filesystem::remove(out / f, ec);
}

PooledResult runPooled(const PoolArgs& a, const std::filesystem::path& out, bool out_given, const harness::Json& plan,
                       const std::string& command, bool show_progress,
                       const std::function<harness::Json(harness::RunPool&)>& body) {
    prepareRunsOutput(out, a, out_given);
    harness::PoolOptions o;
    o.jobs = a.jobs;
    o.runs_dir = out / "runs";
    o.resume = a.resume;
    o.plan = plan;
    o.command = "vroc " + command;
    auto bar = std::make_shared<ProgressBar>(show_progress && harness::mpi::isRoot(), "vroc " + command);
    o.progress = [bar](const harness::PoolProgress& p) { bar->updateRuns(p.done, p.failed, p.total, p.seconds_left); };
    harness::RunPool pool(std::move(o));
    PooledResult r{body(pool), {}};
    bar->finish();
    if (!harness::mpi::isRoot()) return r;   // rank 0 writes the files
    harness::writeDocument(r.doc, out / "metrics.json");
    r.report = std::filesystem::absolute(harness::writeReport({r.doc}, out)).lexically_normal();
    return r;
}

}  // namespace vroc::cli
