// SPDX-License-Identifier: MIT
#include "vroc/harness/commands/report_merge.h"

#include "vroc/core/errors.h"
#include "vroc/harness/documents/html_report.h"
#include "vroc/harness/documents/metrics_document.h"

namespace vroc::harness {

std::filesystem::path rebuildReport(const std::vector<std::filesystem::path>& dirs, const std::filesystem::path& out_dir) {
    if (dirs.empty()) throw InputError("vroc report: expected at least one directory holding a metrics.json");
    std::vector<Json> docs;
    for (const auto& dir : dirs) {
        Json doc = readDocument(dir / "metrics.json");
        if (dirs.size() > 1) doc["title"] = doc.value("title", "") + " [from " + dir.string() + "]";
        docs.push_back(std::move(doc));
    }
    return writeReport(docs, out_dir);
}

}  // namespace vroc::harness
