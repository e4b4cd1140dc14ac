// SPDX-License-Identifier: MIT
// The `vroc play` loop: device -> backend -> HMD model -> renderer, one simulation frame per
// displayed frame, timed stage by stage. Runs on simulated time (deterministic output frames);
// the rates are measured on the wall clock.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "vroc/core/backend.h"
#include "vroc/hmd/hmd_settings.h"
#include "vroc/play/grab_controller.h"

namespace vroc::play {

struct PlayOptions {
    std::string scene_path;
    std::string backend = "bullet";
    std::vector<std::pair<std::string, std::string>> backend_settings;   ///< --set
    std::string device_spec;     ///< "plugin:key=value,..." for the hand; "" = no hand
    std::string head_spec;       ///< head tracker plugin; "" = the scripted head motion
    std::vector<std::pair<std::string, std::string>> hmd_overrides;      ///< --hmd
    int frames = 300;
    int eye_width = 640;         ///< [px]
    int eye_height = 480;        ///< [px]
    std::string out_dir;         ///< frames (PNG), play.json, play.mp4; "" = nothing written
    bool write_frames = true;    ///< PNG per frame (when out_dir is set)
    bool mp4 = false;            ///< also play.mp4 through ffmpeg
    GrabSettings grab;
    std::vector<std::string> plugin_dirs;   ///< extra plugin search directories
};

struct ErrorSummary {            ///< [deg] per-frame registration error statistics
    double mean = 0, rms = 0, p95 = 0, max = 0;
};

struct PlayReport {
    std::string scene_name;
    std::string backend;
    std::string device;
    std::string head;
    std::string gl_renderer;
    int frames = 0;
    double frame_dt = 0;         ///< [s]
    int eye_width = 0, eye_height = 0;
    hmd::HmdSettings hmd;
    std::map<std::string, double> stage_ms;       ///< mean wall time per frame by stage [ms]
    std::map<std::string, double> rates_fps;      ///< simulation, render, loop, loop_with_output
    std::map<std::string, ErrorSummary> registration;   ///< by predictor name
    int registration_points = 0;
    std::vector<ThrowRecord> throws;
    std::vector<std::string> body_names;
    int grabs = 0;
    WarningCounts warnings;
    std::vector<std::string> outputs;             ///< files written
};

/// Runs the loop (backends must be registered). Throws InputError for bad options or scene,
/// RunError for output failures.
PlayReport runPlay(const PlayOptions& options);

/// Writes play.json (format "vroc-play/1"); see docs/hmd.md for the fields.
void writePlayJson(const PlayReport& report, const std::string& path);

}  // namespace vroc::play
