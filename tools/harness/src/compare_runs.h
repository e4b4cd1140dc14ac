// SPDX-License-Identifier: MIT
// The runs `vroc compare` makes per backend: main, twin (perturbed) and re-anchored windows.
#pragma once

#include <filesystem>
#include <vector>

#include "vroc/harness/backend_selection.h"
#include "vroc/harness/compare.h"
#include "vroc/harness/run_trace.h"

namespace vroc::harness {

struct BackendRuns {
    RunTrace main;                                     ///< from the scene's initial state
    RunTrace twin;                                     ///< every virtual body moved by ε along x
    std::vector<std::vector<BodyState>> window_ends;   ///< [anchor] state after one window
    std::vector<double> penetration;                   ///< [m] per frame of main (neutral query)
    std::string state_hash;                            ///< vroc::stateHash of main's final state
    bool deterministic = false;                        ///< a rerun ended with the same state hash (M22)
};

/// Frame indices of the K anchors: evenly spread so that anchor + window fits in the run.
std::vector<std::size_t> anchorFrames(std::size_t frames, int windows, std::int64_t window_frames);

/// The scene's initial states with every virtual body's position moved by `epsilon` [m] along x.
std::vector<BodyState> perturbedStates(const Scene& scene, double epsilon);

/// Writes trajectory.csv, events.csv and step_times.csv of a trace into `dir`.
void writeTraceCsv(const Scene& scene, const RunTrace& trace, const std::filesystem::path& dir);

}  // namespace vroc::harness
