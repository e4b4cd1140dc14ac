// SPDX-License-Identifier: MIT
// The file of one finished run, `<runs_dir>/<job>.json` (format "vroc-run-result/1"): the job's id,
// the hash of the plan it belongs to and its result, written around the result's own text so the
// result is never re-serialised. This is what `--resume` reads back (docs/harness.md).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "vroc/harness/documents/metrics_document.h"

namespace vroc::harness::pool_detail {

/// The plan's hash (FNV-1a 64 of its JSON text, in hex) that marks each run file.
std::string planHash(const Json& plan);

/// Writes `<dir>/<job>.json` atomically; nothing when `dir` is empty (a pool that keeps no files).
void writeRunFile(const std::filesystem::path& dir, const std::string& job, const std::string& plan_hash,
                  const std::string& result_text);

/// The result of a finished run on disk, if it belongs to this plan; throws InputError if it
/// belongs to another plan (the folder holds some other command's runs).
std::optional<Json> readRunFile(const std::filesystem::path& path, const std::string& job,
                                const std::string& plan_hash);

}  // namespace vroc::harness::pool_detail
