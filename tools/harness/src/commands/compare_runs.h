// SPDX-License-Identifier: MIT
// Helpers for the runs `vroc compare` makes per backend (BackendRuns, compare.h): main, twin
// (perturbed) and re-anchored windows.
#pragma once

#include <filesystem>
#include <vector>

#include "vroc/harness/commands/compare.h"
#include "vroc/harness/runs/backend_selection.h"
#include "vroc/harness/runs/run_trace.h"

namespace vroc::harness {

/// Frame indices of the K anchors: evenly spread so that anchor + window fits in the run.
std::vector<std::size_t> anchorFrames(std::size_t frames, int windows, std::int64_t window_frames);

/// The scene's initial states with every virtual body's position moved by `epsilon` [m] along x.
std::vector<BodyState> perturbedStates(const Scene& scene, double epsilon);

/// Writes trajectory.csv, events.csv and step_times.csv of a trace into `dir`.
void writeTraceCsv(const Scene& scene, const RunTrace& trace, const std::filesystem::path& dir);

}  // namespace vroc::harness
