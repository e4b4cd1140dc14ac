// SPDX-License-Identifier: MIT
// What one input directory of `vroc view` holds, read from its run.json or metrics.json (the
// boundary where those files are read; the viewer needs only these few fields).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "vroc/harness/commands/ensemble.h"

namespace vroc::viewer {

/// A recorded run: one backend's trajectory.csv and events.csv.
struct RecordedRunFiles {
    std::string backend;               ///< registry name
    std::string label;                 ///< shown on the page
    std::filesystem::path trajectory;  ///< trajectory.csv
    std::filesystem::path events;      ///< events.csv (may be absent: no markers)
    std::size_t expected_frames = 0;   ///< frames the run recorded (steps + 1); 0 unknown
};

/// An ensemble's members, to replay (ensembles keep no trajectories).
struct EnsembleReplayPlan {
    struct Backend {
        std::string name;                             ///< registry name
        std::map<std::string, std::string> settings;  ///< resolved, as metrics.json lists them
    };
    std::vector<Backend> backends;
    harness::Perturbation perturb;
    int members = 0;
    double duration = 0;  ///< [s]
    double frame_dt = 0;  ///< [s]
    std::uint64_t seed = 1;
    /// The final state hash each member recorded (runs/member-<backend>-<m>.json), by (backend, m).
    std::map<std::pair<std::string, int>, std::string> recorded_hashes;
};

struct RunDirectory {
    std::filesystem::path dir;
    std::string command;  ///< "run", "compare" or "ensemble"
    std::string title;
    std::string scene_file;              ///< as recorded (absolute, or relative to the working directory)
    std::string scene_sha256;            ///< hex, as recorded
    std::vector<RecordedRunFiles> runs;  ///< run, compare
    EnsembleReplayPlan ensemble;         ///< ensemble
};

/// Reads `dir`'s run.json (a `vroc run`) or metrics.json (compare, ensemble). Throws InputError
/// naming the file for a directory that is neither, an incomplete run or an unreadable field.
RunDirectory readRunDirectory(const std::filesystem::path& dir);

}  // namespace vroc::viewer
