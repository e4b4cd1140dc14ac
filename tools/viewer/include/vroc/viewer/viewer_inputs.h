// SPDX-License-Identifier: MIT
// Builds the viewer's data (viewer_data.h) from the output directories of `vroc run`,
// `vroc compare` and `vroc ensemble` (docs/viewer.md, "Inputs").
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "vroc/viewer/viewer_data.h"

namespace vroc::viewer {

struct ViewerOptions {
    std::size_t max_frames = 2000;          ///< [frames] kept at most; longer runs are subsampled (noted on the page)
    std::size_t max_pose_bytes = 6u << 20;  ///< [bytes] of packed poses (24 per moving body per frame per run);
                                            ///< beyond it frames are subsampled too (6 MiB: 200 bodies x 300
                                            ///< frames x 4 runs fit, and the page stays under 10 MB)
    int max_members = 8;                    ///< [members] of an ensemble replayed per backend (0, 1, ...)
    bool penetration = true;                ///< flag bodies deeper than the collision distance (neutral distance)
    std::size_t penetration_max_bodies = 500;  ///< [bodies] moving; above it no flags (noted): the pair
                                               ///< distances cost about N^2 x frames
    std::string scene_file;                    ///< "" = the scene the directories recorded; else this file
};

/// Reads every directory: a `vroc run` output (run.json, trajectory.csv, events.csv), a
/// `vroc compare` output (metrics.json and <backend>/trajectory.csv, events.csv; with both footings
/// <key>/, e.g. bullet-equal/, each run labelled by its footing) or a
/// `vroc ensemble` output (metrics.json; its members are replayed here, since ensembles keep no
/// trajectories). All must be of one scene at one frame step. Throws InputError naming the file and
/// what was expected (a missing or truncated trajectory, a scene changed since the run, ...).
/// Ensembles replay through BackendRegistry::global(): the backends must be registered.
ViewerData loadViewerData(const std::vector<std::filesystem::path>& dirs, const ViewerOptions& options = {});

}  // namespace vroc::viewer
