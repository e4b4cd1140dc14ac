// SPDX-License-Identifier: MIT
// `vroc run SCENE --backend NAME`: simulate one scene on one backend and record it (docs/cli.md),
// with its 3D replay, view.html (docs/viewer.md).
#include <csignal>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "command.h"
#include "progress_bar.h"
#include "report_view.h"
#include "vroc/audio/sound_recorder.h"
#include "vroc/core/backend_registry.h"
#include "vroc/core/errors.h"
#include "vroc/core/recording/output_dir.h"
#include "vroc/core/recording/run_recorder.h"
#include "vroc/core/scene_loader.h"
#include "vroc/play/tracked_driver.h"
#include "vroc/plugin/plugin_host.h"

namespace vroc::cli {
namespace {
namespace fs = std::filesystem;

/// Simulated time when --duration is not given (the scene format has no duration).
constexpr double kDefaultDuration = 5.0;   // [s]

struct RunOptions {
    std::string scene_file;
    std::string backend;
    std::optional<double> duration;   ///< [s]
    std::optional<double> dt;         ///< [s]
    std::string out_dir;
    std::vector<std::string> assignments;   ///< --set key=value, in order (later wins)
    std::vector<std::string> track;         ///< --track BODY=SPEC[#SENSOR]: tracked bodies' devices
    std::string sound;                      ///< --sound: WAV of the impacts ("" = none)
    std::string sound_level = "normalize";  ///< --sound-level
    bool quiet = false;
    bool no_view = false;           ///< --no-view: no view.html
    bool view_penetration = false;  ///< --view-penetration: view.html with the penetration highlight (costly)
};

// Ctrl-C and SIGTERM stop the run between frames; the recorder then removes its temporary files.
volatile std::sig_atomic_t g_interrupted = 0;
extern "C" void onInterrupt(int) { g_interrupted = 1; }

std::string formatNumber(double value) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", value);
    return buf;
}

double positiveSeconds(const std::optional<double>& value, double fallback, const char* option) {
    if (!value) return fallback;
    if (!std::isfinite(*value) || *value <= 0)
        throw InputError(std::string(option) + ": expected a positive number of seconds, got " + formatNumber(*value));
    return *value;
}

void printSummary(const recording::RunRecord& r, const fs::path& dir) {
    std::printf("vroc: %s on %s: %lld steps of %.6g s in %.3f s wall, step p50 %.1f us, p99 %.1f us, "
                "%llu collisions, state_hash %s\n",
                r.scene_name.c_str(), r.backend_name.c_str(), static_cast<long long>(r.steps), r.frame_dt,
                r.wall_time_s, r.step_wall_us.p50, r.step_wall_us.p99,
                static_cast<unsigned long long>(r.collision_count), r.state_hash.c_str());
    std::printf("vroc: output in %s\n", fs::absolute(dir).lexically_normal().string().c_str());
}

int run(const RunOptions& options, const Context& context) {
    // Cheap checks first, so bad input never costs a scene load or leaves a directory behind.
    if (options.backend.empty()) {
        std::string known;
        for (const auto* info : BackendRegistry::global().all()) known += (known.empty() ? "" : ", ") + info->name;
        throw InputError("--backend is required (known: " + known + ")");
    }
    const BackendInfo& backend = BackendRegistry::global().require(options.backend);
    std::vector<std::pair<std::string, std::string>> overrides;
    for (const auto& text : options.assignments) overrides.push_back(splitAssignment(text));
    const double duration = positiveSeconds(options.duration, kDefaultDuration, "--duration");
    if (options.dt) positiveSeconds(options.dt, 0, "--dt");
    std::vector<play::TrackOverride> track;
    for (const auto& text : options.track) track.push_back(play::parseTrackOption(text));

    recording::RunRequest request;
    request.settings = resolveSettings(backend.settings, overrides);
    const Scene scene = loadScene(options.scene_file);
    request.scene = &scene;
    request.backend = &backend;
    request.scene_file = options.scene_file;
    request.frame_dt = positiveSeconds(options.dt, scene.frame_dt, "--dt");
    request.duration = duration;
    frameCount(request.duration, request.frame_dt);   // range check before touching disk
    request.out_dir = options.out_dir.empty() ? recording::timestampedOutputDir({scene.name, backend.name})
                                              : fs::path(options.out_dir);
    request.command_line = context.command_line;

    // --track: those tracked bodies follow their devices, read at simulation time before each frame.
    // Without it every tracked body moves at its file velocities (deterministic), the scene's
    // tracking.device notwithstanding.
    std::optional<plugins::PluginHost> plugin_host;
    std::optional<play::TrackedDriver> tracked;
    if (!track.empty()) {
        plugin_host.emplace();
        tracked.emplace(scene, *plugin_host, track, /*use_scene_devices=*/false);
        request.before_frame = [&tracked](Backend& b, double t) { tracked->update(t, b); };
    }

    // --sound: checked (settings, materials, a writable place) before anything is simulated.
    std::optional<audio::SoundRecorder> sound;
    std::optional<audio::SoundSummary> sound_summary;
    if (!options.sound.empty()) {
        audio::SoundSettings settings;
        settings.level = audio::parseOutputLevel(options.sound_level, "--sound-level");
        const double end = static_cast<double>(frameCount(request.duration, request.frame_dt)) *
                           request.frame_dt;
        sound.emplace(scene, request.frame_dt, end, options.sound, settings);
        request.on_events = [&sound](const std::vector<CollisionEvent>& events) { sound->addEvents(events); };
        request.finish_outputs = [&](recording::RunRecord& record) {
            sound_summary = sound->finish(record.simulated_time);
            record.outputs["sound"] = {options.sound, sound_summary->describe()};
            record.outputs["sound_events"] = {sound_summary->events_csv.string(),
                                              "every collision event: t,body_a,body_b,impulse,threshold,sample,status"};
        };
    }

    ProgressBar bar(context.stderr_is_terminal && !options.quiet, scene.name + " on " + backend.name);
    g_interrupted = 0;
    std::signal(SIGINT, onInterrupt);
    std::signal(SIGTERM, onInterrupt);
    request.progress = [&bar](std::int64_t done, std::int64_t total) {
        bar.update(done, total);
        return g_interrupted == 0;
    };
    const recording::RunRecord record = recording::recordRun(request);
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    if (!options.quiet) printSummary(record, request.out_dir);
    if (!options.quiet && sound_summary)
        std::printf("vroc: sound in %s: %s\n", fs::absolute(sound_summary->wav).lexically_normal().string().c_str(),
                    sound_summary->describe().c_str());
    // After run.json: the view reads the finished run as `vroc view` would (a failure is a line on
    // stderr, the run stands). Without the penetration highlight unless asked: the highlight (pair
    // distances at every frame) can cost more than the run itself.
    if (!options.no_view) writeReportView(request.out_dir, "run", options.quiet, options.view_penetration);
    return 0;
}

Action setupRun(CLI::App& sub, const Context& context) {
    auto o = std::make_shared<RunOptions>();
    sub.add_option("scene", o->scene_file, "Scene file (vroc-scene/1 JSON, see docs/scene-format.md)")->required();
    sub.add_option("--backend,-b", o->backend, "Physics backend to use (see `vroc backends`)");
    sub.add_option("--duration", o->duration, "Simulated time [s] (default 5)");
    sub.add_option("--dt", o->dt, "Frame step [s] (default: the scene's frame_dt)");
    sub.add_option("--out,-o", o->out_dir,
                   "Output directory (default runs/<scene>-<backend>-<YYYYmmdd-HHMMSS UTC>/); "
                   "created if missing, an earlier run in it is replaced");
    sub.add_option("--set", o->assignments, "Backend setting key=value, repeatable (keys: `vroc backends`)")
        ->allow_extra_args(false)   // one value per --set, so `--set k=v SCENE` leaves SCENE alone
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    sub.add_option("--track", o->track,
                   "Tracked body's device BODY=PLUGIN_SPEC[#SENSOR], repeatable (default: tracked bodies move at "
                   "their file velocities)")
        ->allow_extra_args(false)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    sub.add_option("--sound", o->sound,
                   "Also write the impacts as a WAV (modal synthesis per material, docs/hmd.md#impact-sound) "
                   "and <stem>_events.csv next to it");
    sub.add_option("--sound-level", o->sound_level,
                   "normalize: peak at -1 dBFS (default); fixed: same impulse, same level, soft limiter");
    sub.add_flag("--quiet,-q", o->quiet, "No progress bar and no summary; only errors");
    sub.add_flag("--no-view", o->no_view, "Do not write view.html, the run's 3D replay (docs/viewer.md)");
    sub.add_flag("--view-penetration", o->view_penetration,
                 "Highlight penetration in view.html too (costly for many bodies; `vroc view DIR` also does it)");
    sub.footer(
        "Writes trajectory.csv, events.csv and run.json (last, atomically) into the output directory,\n"
        "then view.html, the run's 3D replay for a browser, without the penetration highlight unless\n"
        "--view-penetration (--no-view: no view.html; docs/viewer.md);\n"
        "--sound also writes the WAV and <stem>_events.csv (before run.json, atomically).\n"
        "Exit codes: 0 success, 2 bad input or usage, 3 failure while running.");
    return [o, context] { return run(*o, context); };
}

}  // namespace

Command makeRunCommand() {
    return {"run", "Simulate a scene on one backend; write trajectory.csv, events.csv, run.json", &setupRun};
}

}  // namespace vroc::cli
