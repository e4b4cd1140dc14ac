// SPDX-License-Identifier: MIT
#include "vroc/harness/commands/pooled_command.h"

#include <system_error>

#include "vroc/core/errors.h"
#include "vroc/core/recording/atomic_output.h"
#include "vroc/harness/documents/html_report.h"
#include "vroc/harness/documents/metrics_document.h"
#include "vroc/harness/pool/mpi_world.h"

namespace vroc::harness {

void prepareRunsOutput(const std::filesystem::path& out, bool resume, bool out_given) {
    if (resume && !out_given) throw InputError("--resume: give --out, the output folder of the interrupted command");
    if (resume && !std::filesystem::is_directory(out / "runs"))
        throw InputError("--resume: " + (out / "runs").string() + " does not exist (nothing to resume; run without --resume)");
    if (!mpi::isRoot()) return;
    recording::prepareOutputDirectory(out);
    std::error_code ec;
    for (const char* f : {"metrics.json", "report.html"}) std::filesystem::remove(out / f, ec);
}

PooledOutput runPooledCommand(const PooledCommand& command, const std::function<Json(RunPool&)>& body) {
    const bool files = !command.out.empty();
    if (files) prepareRunsOutput(command.out, command.resume, command.out_given);
    PoolOptions o;
    o.jobs = command.jobs;
    if (files) o.runs_dir = command.out / "runs";
    o.resume = command.resume;
    o.plan = command.plan;
    o.command = command.command;
    o.progress = command.progress;
    RunPool pool(std::move(o));
    PooledOutput r{body(pool), {}};
    if (!files || !mpi::isRoot()) return r;   // rank 0 writes the files
    writeDocument(r.doc, command.out / "metrics.json");
    r.report = std::filesystem::absolute(writeReport({r.doc}, command.out)).lexically_normal();
    return r;
}

}  // namespace vroc::harness
