// SPDX-License-Identifier: MIT
// The `vroc play` loop: device -> backend -> HMD model -> renderer, one simulation frame per
// displayed frame, timed stage by stage. Runs on simulated time (deterministic output frames) as
// fast as it can, or with `realtime` paced to the wall clock; the rates are measured on the wall clock.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "vroc/audio/sound_settings.h"
#include "vroc/core/backend.h"
#include "vroc/hmd/hmd_settings.h"
#include "vroc/play/frame_pacer.h"
#include "vroc/play/grab_controller.h"
#include "vroc/play/tracked_driver.h"

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
    std::string sound_path;      ///< --sound: WAV of the impacts (and <stem>_events.csv); "" = none
    audio::SoundSettings sound;  ///< --sound-level and the rest (docs/hmd.md#impact-sound)
    /// Pace frames to the wall clock at the scene's frame_dt and read devices at host time
    /// (FramePacer, docs/hmd.md "Real time"); false: as fast as possible, simulation time drives
    /// the devices (deterministic).
    bool realtime = false;
    std::vector<TrackOverride> track;       ///< --track: tracked bodies' devices (override the scene's)
    /// Called after each frame's step (frame index, backend), e.g. by tests that follow bodies.
    std::function<void(int, const Backend&)> on_frame;
};

/// One frame's reading of a device, kept in the report (PlayReport::head_trace, hand_trace).
struct DeviceFrame {
    int frame = 0;
    bool valid = false;
    std::int64_t sample_time_ns = 0;   ///< [ns] host clock
    std::uint64_t sequence = 0;
    Pose pose;                         ///< sensor -> world as the device gave it
};

/// A tracked body driven by a device (TrackedDriver), for the report.
struct TrackedReport {
    std::string body, device;
    int sensor = 0;
    std::int64_t frames_set = 0, frames_without_sample = 0, velocities_estimated = 0;
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
    std::string sound;                            ///< --sound: one line on the WAV written; "" if none
    // Force output (the grab coupling's reaction on the hand; GrabController::handWrench).
    bool hand_accepts_force = false;              ///< the hand device takes forces
    std::int64_t forces_sent = 0;                 ///< forces the hand device took
    std::int64_t forces_rejected = 0;             ///< refused by the loader or failed in the plugin
    // Real time (PlayOptions::realtime).
    bool realtime = false;
    int frames_missed = 0;                        ///< frames done after their deadline
    double worst_lateness_ms = 0;                 ///< [ms] the latest a frame was done past its deadline
    /// [ms] device sample (PoseSample::time_ns) to frame done (after render and write), by device
    /// ("head", "hand", "track:BODY"); real time only.
    std::map<std::string, LatencySummary> latency_ms;
    std::vector<DeviceFrame> head_trace, hand_trace;   ///< per frame, when the device is a plugin
    std::vector<TrackedReport> tracked;
};

/// Runs the loop (backends must be registered). Throws InputError for bad options or scene,
/// RunError for output failures.
PlayReport runPlay(const PlayOptions& options);

/// Writes play.json (format "vroc-play/1"); see docs/hmd.md for the fields.
void writePlayJson(const PlayReport& report, const std::string& path);

}  // namespace vroc::play
