// SPDX-License-Identifier: MIT
// Runs one backend on one scene for a number of frames and records trajectory.csv, events.csv and
// run.json into a directory (atomic_output.h). `vroc run` and the harness commands share it.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "vroc/core/backend.h"
#include "vroc/core/frame_loop.h"
#include "vroc/core/scene.h"
#include "vroc/core/settings.h"
#include "vroc/core/recording/run_record.h"

namespace vroc::recording {

struct RunRequest {
    const Scene* scene = nullptr;                ///< not owned; must outlive the call
    const BackendInfo* backend = nullptr;        ///< not owned
    Settings settings;                           ///< resolved against backend->settings
    std::string scene_file;                      ///< for run.json
    double frame_dt = 0;                         ///< [s] > 0, finite
    double duration = 0;                         ///< [s] > 0, finite; frameCount(duration, frame_dt) frames
    std::filesystem::path out_dir;
    std::string command_line;                    ///< for run.json
    /// Called after each frame with (frames done, total); returning false stops the run, which
    /// then fails with RunError("interrupted ...") and leaves no run.json. May be empty.
    std::function<bool(std::int64_t, std::int64_t)> progress;
    /// Called after each frame with that frame's collision events (as written to events.csv), e.g.
    /// for `vroc run --sound`. May be empty.
    std::function<void(const std::vector<CollisionEvent>&)> on_events;
    /// Called after the last frame, once trajectory.csv and events.csv are in place and before
    /// run.json is written: writes further outputs (atomically) and names them in
    /// RunRecord::outputs. If it throws, the run fails like any other: no run.json. May be empty.
    std::function<void(RunRecord&)> finish_outputs;
    /// Called before each frame's stepFrame with the backend and the frame's start time [s], e.g.
    /// for `vroc run --track` (tracked bodies take their device's pose). May be empty.
    std::function<void(Backend&, double)> before_frame;
};

/// Validates the request (InputError), prepares the output directory (InputError if unwritable),
/// creates the backend (its InputError passes through), steps and records. Failures while stepping
/// or writing throw RunError; in every failure case no run.json is written and temporary files are
/// removed. Returns the record that was written to run.json.
RunRecord recordRun(const RunRequest& request);

}  // namespace vroc::recording
