// SPDX-License-Identifier: MIT
// The only place that writes run.json (nlohmann/json stays out of headers).
#include "vroc/core/recording/run_record.h"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "vroc/core/recording/output_dir.h"

namespace vroc::recording {
namespace {

// Nearest-rank percentile of sorted values: the smallest value with at least p % at or below it.
double nearestRank(const std::vector<double>& sorted, double p) {
    const double rank = std::ceil(p / 100.0 * static_cast<double>(sorted.size()));
    const std::size_t index = rank < 1 ? 0 : static_cast<std::size_t>(rank) - 1;
    return sorted[std::min(index, sorted.size() - 1)];
}

nlohmann::ordered_json finiteOrNull(double value) {
    return std::isfinite(value) ? nlohmann::ordered_json(value) : nlohmann::ordered_json(nullptr);
}

}  // namespace

StepTimes summarizeStepTimes(std::vector<double> step_us) {
    StepTimes out;
    if (step_us.empty()) return out;
    std::sort(step_us.begin(), step_us.end());
    out.p50 = nearestRank(step_us, 50);
    out.p90 = nearestRank(step_us, 90);
    out.p99 = nearestRank(step_us, 99);
    out.max = step_us.back();
    double sum = 0;
    for (double v : step_us) sum += v;
    out.mean = sum / static_cast<double>(step_us.size());
    return out;
}

std::string toJson(const RunRecord& r) {
    // ordered_json keeps the order below (what a reader looks for first), not alphabetical.
    using json = nlohmann::ordered_json;
    json statistics = json::object();
    for (const auto& [key, value] : r.statistics) statistics[key] = finiteOrNull(value);
    json warnings = json::object();
    for (const auto& [kind, count] : r.warnings) warnings[kind] = count;

    json j = {
        {"format", kRunFormat},
        {"scene", {{"name", r.scene_name}, {"file", r.scene_file}, {"sha256", r.scene_sha256},
                   {"bodies", r.body_count}, {"virtual_bodies", r.virtual_body_count}}},
        {"backend", {{"name", r.backend_name}, {"version", r.backend_version}, {"deviations", r.backend_deviations}}},
        {"settings", r.settings},
        {"frame_dt", r.frame_dt},
        {"duration", r.duration},
        {"steps", r.steps},
        {"simulated_time", r.simulated_time},
        {"start_time_utc", r.start_time_utc},
        {"wall_time_s", r.wall_time_s},
        {"step_wall_time_us", {{"p50", r.step_wall_us.p50}, {"p90", r.step_wall_us.p90},
                               {"p99", r.step_wall_us.p99}, {"mean", r.step_wall_us.mean},
                               {"max", r.step_wall_us.max}}},
        {"collision_count", r.collision_count},
        {"pair_count", r.pair_count},
        {"warnings", warnings},
        {"statistics", statistics},
        {"state_hash", r.state_hash},
        {"build", {{"version", r.build.version}, {"commit", r.build.commit},
                   {"compiler", r.build.compiler}, {"flags", r.build.flags}}},
        {"command_line", r.command_line},
    };
    if (!r.outputs.empty()) {
        json outputs = json::object();
        for (const auto& [role, output] : r.outputs)
            outputs[role] = {{"file", output.file}, {"description", output.description}};
        j["outputs"] = outputs;
    }
    // nlohmann prints doubles round-trip exact (shortest representation that reads back equal).
    return j.dump(2) + "\n";
}

std::string utcNowIso8601() { return utcNow("%Y-%m-%dT%H:%M:%SZ"); }

}  // namespace vroc::recording
