// SPDX-License-Identifier: MIT
// run.json: everything needed to know what a run was and how it went (format "vroc-run/1",
// documented in docs/cli.md). Written last, atomically: its presence marks a complete run.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "vroc/core/backend.h"
#include "vroc/core/build_info.h"

namespace vroc::recording {

inline constexpr const char* kRunFormat = "vroc-run/1";

/// Per-step wall time summary [µs]; percentiles by nearest rank.
struct StepTimes {
    double p50 = 0, p90 = 0, p99 = 0, mean = 0, max = 0;
};
/// Summarises per-step wall times [µs] (empty input gives all zeros).
StepTimes summarizeStepTimes(std::vector<double> step_us);

/// A file a run wrote besides trajectory.csv, events.csv and run.json (e.g. `vroc run --sound`).
struct RunOutput {
    std::string file;          ///< path as given (relative to the working directory, or absolute)
    std::string description;   ///< one line: what it holds and how it was made
};

struct RunRecord {
    std::string scene_name;
    std::string scene_file;                    ///< as given on the command line
    std::string scene_sha256;                  ///< hex SHA-256 of the scene file bytes
    std::size_t body_count = 0;                ///< all bodies
    std::size_t virtual_body_count = 0;        ///< rows per frame in trajectory.csv
    std::string backend_name;
    std::string backend_version;
    std::vector<std::string> backend_deviations;   ///< from the engine's own defaults, with why
    std::map<std::string, std::string> settings;   ///< every effective setting, as written
    double frame_dt = 0;                       ///< [s]
    double duration = 0;                       ///< [s] requested
    std::int64_t steps = 0;                    ///< frames stepped
    double simulated_time = 0;                 ///< [s] backend time at the end
    std::string start_time_utc;                ///< ISO 8601, e.g. "2026-11-29T11:07:11Z"
    double wall_time_s = 0;                    ///< [s] whole run incl. writing
    StepTimes step_wall_us;                    ///< stepFrame only
    std::uint64_t collision_count = 0;         ///< rows of events.csv
    std::uint64_t pair_count = 0;              ///< distinct pairs that collided
    WarningCounts warnings;
    Statistics statistics;
    std::string state_hash;                    ///< 16 hex digits, vroc::stateHash of the final state
    BuildInfo build;
    std::string command_line;                  ///< how the run was started ("" if not by the CLI)
    std::map<std::string, RunOutput> outputs;  ///< further files by role ("sound"); omitted from run.json if empty
};

/// Pretty-printed JSON text (2-space indent, trailing newline). Non-finite statistics become null.
std::string toJson(const RunRecord& record);

/// Current UTC time as ISO 8601 with seconds, e.g. "2026-11-29T11:07:11Z".
std::string utcNowIso8601();

}  // namespace vroc::recording
