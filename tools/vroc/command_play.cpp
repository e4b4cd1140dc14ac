// SPDX-License-Identifier: MIT
// `vroc play`: the interactive loop offscreen — device -> backend -> HMD model -> renderer —
// writing frames, an optional MP4 and play.json (docs/hmd.md).
#include <cstdio>
#include <memory>

#include <CLI/CLI.hpp>

#include "command.h"
#include "vroc/core/settings.h"
#include "vroc/hmd/hmd_settings.h"
#include "vroc/play/play_loop.h"

namespace vroc::cli {
namespace {

struct PlayCliOptions {
    play::PlayOptions play;
    std::vector<std::string> hmd;
    std::vector<std::string> set;
    std::vector<std::string> track;
    std::string sound_level = "normalize";
    bool no_frames = false;
    bool quiet = false;
};

int runPlayCommand(PlayCliOptions& o) {
    for (const auto& text : o.hmd) o.play.hmd_overrides.push_back(splitAssignment(text));
    for (const auto& text : o.set) o.play.backend_settings.push_back(splitAssignment(text));
    o.play.write_frames = !o.no_frames;
    for (const auto& text : o.track) o.play.track.push_back(play::parseTrackOption(text));
    o.play.sound.level = audio::parseOutputLevel(o.sound_level, "--sound-level");
    const play::PlayReport r = play::runPlay(o.play);
    if (!o.play.out_dir.empty()) play::writePlayJson(r, o.play.out_dir + "/play.json");
    if (!o.quiet) {
        std::printf("%d frames of %s on %s (%s), %dx%d per eye\n", r.frames, r.scene_name.c_str(),
                    r.backend.c_str(), r.gl_renderer.c_str(), r.eye_width, r.eye_height);
        std::printf("rates [frames/s]: simulation %.0f, render %.0f, loop %.0f, with output %.0f\n",
                    r.rates_fps.at("simulation"), r.rates_fps.at("render"), r.rates_fps.at("loop"),
                    r.rates_fps.at("loop_with_output"));
        for (const auto& [name, s] : r.registration)
            std::printf("registration error, %s: mean %.2f deg, p95 %.2f deg, max %.2f deg\n", name.c_str(), s.mean,
                        s.p95, s.max);
        if (r.realtime)
            std::printf("registration error: not modelled in real time (the newest head sample is drawn; the "
                        "measured latency below is the chain's)\n");
        std::printf("grabs %d, throws %zu\n", r.grabs, r.throws.size());
        if (r.hand_accepts_force)
            std::printf("forces sent to the hand %lld (rejected %lld)\n", static_cast<long long>(r.forces_sent),
                        static_cast<long long>(r.forces_rejected));
        for (const play::TrackedReport& t : r.tracked)
            std::printf("tracked %s <- %s#%d: %lld frames set, %lld without a sample\n", t.body.c_str(), t.device.c_str(),
                        t.sensor, static_cast<long long>(t.frames_set), static_cast<long long>(t.frames_without_sample));
        if (r.realtime) {
            std::printf("real time: %d of %d frames missed their deadline (worst %.2f ms late)\n", r.frames_missed,
                        r.frames, r.worst_lateness_ms);
            for (const auto& [device, l] : r.latency_ms)
                std::printf("latency %s sample -> frame done [ms]: mean %.2f, p50 %.2f, p95 %.2f, max %.2f (%d frames)\n",
                            device.c_str(), l.mean, l.p50, l.p95, l.max, l.count);
        }
        if (!r.sound.empty()) std::printf("sound %s: %s\n", o.play.sound_path.c_str(), r.sound.c_str());
        if (!o.play.out_dir.empty()) std::printf("wrote %s/play.json\n", o.play.out_dir.c_str());
    }
    return 0;
}

std::string hmdKeysHelp() {
    std::string help = "HMD setting key=value, repeatable. Keys:";
    for (const SettingSpec& spec : hmd::hmdSettingSpecs()) help += "\n  " + spec.describe();
    return help;
}

Action setupPlay(CLI::App& sub, const Context&) {
    auto o = std::make_shared<PlayCliOptions>();
    sub.add_option("scene", o->play.scene_path, "Scene file (vroc-scene/1 JSON)")->required();
    sub.add_option("--backend,-b", o->play.backend, "Physics backend (see `vroc backends`)");
    sub.add_option("--set", o->set, "Backend setting key=value, repeatable");
    sub.add_option("--device", o->play.device_spec,
                   "Hand device plugin spec, e.g. analytic:motion=throw,x=0.7,z=1.3 (button 0 grabs)");
    sub.add_option("--head", o->play.head_spec,
                   "Head tracker plugin spec (sensor z up, looking along +y); default: scripted head motion");
    sub.add_option("--hmd", o->hmd, hmdKeysHelp());
    sub.add_option("--frames,-n", o->play.frames, "Frames to run (default 300)");
    sub.add_option("--width", o->play.eye_width, "Image width per eye [px] (default 640)");
    sub.add_option("--height", o->play.eye_height, "Image height [px] (default 480)");
    sub.add_option("--out,-o", o->play.out_dir, "Output directory: frame_NNNNN.png, play.json, play.mp4");
    sub.add_flag("--mp4", o->play.mp4, "Also encode play.mp4 (ffmpeg, libx264, yuv420p)");
    sub.add_flag("--no-frames", o->no_frames, "Do not write PNG frames (play.json and --mp4 still written)");
    sub.add_option("--grab-reach", o->play.grab.reach, "Grab reach beyond an object's bounding radius [m] (default 0.15)");
    sub.add_option("--plugin-dir", o->play.plugin_dirs, "Extra plugin search directory, repeatable");
    sub.add_flag("--realtime", o->play.realtime,
                 "Pace frames to the wall clock at the scene's frame_dt, read devices at host time and report "
                 "latency and missed frames (default: as fast as possible on simulated time)");
    sub.add_option("--track", o->track,
                   "Tracked body's device BODY=PLUGIN_SPEC[#SENSOR], repeatable; overrides the scene's tracking.device")
        ->allow_extra_args(false)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    sub.add_option("--sound", o->play.sound_path,
                   "Also write the impacts as a WAV (and <stem>_events.csv next to it; docs/hmd.md#impact-sound)");
    sub.add_option("--sound-level", o->sound_level,
                   "normalize: peak at -1 dBFS (default); fixed: same impulse, same level, soft limiter");
    sub.add_flag("--quiet,-q", o->quiet, "No summary");
    return [o] { return runPlayCommand(*o); };
}

}  // namespace

Command makePlayCommand() {
    return {"play", "Run device -> backend -> HMD model -> OSMesa renderer; write frames and play.json", &setupPlay};
}

}  // namespace vroc::cli
