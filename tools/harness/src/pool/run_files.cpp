// SPDX-License-Identifier: MIT
#include "run_files.h"

#include <cstdint>
#include <fstream>
#include <sstream>

#include "vroc/core/errors.h"
#include "vroc/core/recording/atomic_output.h"
#include "vroc/core/state_hash.h"

namespace vroc::harness::pool_detail {
namespace {

constexpr const char* kRunFormat = "vroc-run-result/1";

std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string fileText(const std::string& job, const std::string& plan_hash, const std::string& result_text) {
    // Written by hand around the result's own text so the result is never re-serialised.
    return std::string("{\"format\":\"") + kRunFormat + "\",\"job\":" + Json(job).dump() + ",\"plan_hash\":\"" +
           plan_hash + "\",\"result\":" + result_text + "}\n";
}

}  // namespace

std::string planHash(const Json& plan) {
    const std::string text = plan.dump();
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a 64
    for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
    return hashToHex(h);
}

void writeRunFile(const std::filesystem::path& dir, const std::string& job, const std::string& plan_hash,
                  const std::string& result_text) {
    if (dir.empty()) return;
    recording::AtomicFile f(dir / (job + ".json"));
    f.write(fileText(job, plan_hash, result_text));
    f.commit();
}

std::optional<Json> readRunFile(const std::filesystem::path& path, const std::string& job,
                                const std::string& plan_hash) {
    if (!std::filesystem::exists(path)) return std::nullopt;
    Json doc = Json::parse(readFile(path), nullptr, false);
    if (doc.is_discarded() || !doc.is_object() || doc.value("format", "") != kRunFormat || doc.value("job", "") != job)
        throw InputError(path.string() + ": not a finished run of job '" + job + "' (expected " + kRunFormat +
                         "); remove it or use a new --out");
    if (doc.value("plan_hash", "") != plan_hash)
        throw InputError(path.string() + ": written by a different plan (hash " + doc.value("plan_hash", "?") +
                         ", this command's is " + plan_hash +
                         "): --resume needs the same scene, options and build; use a new --out or drop --resume");
    return std::move(doc["result"]);
}

}  // namespace vroc::harness::pool_detail
