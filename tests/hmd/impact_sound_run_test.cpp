// SPDX-License-Identifier: MIT
// The impact sound of real native runs, recorded as `vroc run --sound` records it (recordRun with
// the sound hooks): a ball dropped on a floor sounds at its bounces, each onset found in the WAV
// read back within one sample of the event in the run's events.csv, louder for a larger impulse;
// a box resting on (or settling onto) a floor is silent once it rests.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "impact_sound_test.h"
#include "vroc/audio/sound_recorder.h"
#include "vroc/audio/wav_file.h"
#include "vroc/core/backend_registry.h"
#include "vroc/core/recording/run_recorder.h"
#include "vroc/core/scene_loader.h"
#include "vroc/native/native_backend.h"

namespace vroc::audio {
namespace {
namespace fs = std::filesystem;

struct EventRow {
    double t = 0;
    std::string body_a, body_b;
    double impulse = 0;
};

// events.csv of the run: t,body_a,body_b,px,py,pz,nx,ny,nz,impulse (docs/cli.md).
std::vector<EventRow> readEvents(const fs::path& path) {
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "t,body_a,body_b,px,py,pz,nx,ny,nz,impulse");
    std::vector<EventRow> rows;
    while (std::getline(in, line)) {
        std::vector<std::string> f;
        std::stringstream fields(line);
        for (std::string x; std::getline(fields, x, ',');) f.push_back(x);
        EXPECT_EQ(f.size(), 10u) << line;
        if (f.size() == 10u) rows.push_back({std::stod(f[0]), f[1], f[2], std::stod(f[9])});
    }
    return rows;
}

struct SoundRun {
    std::vector<EventRow> events;
    WavData wav;
    SoundSummary summary;
    nlohmann::json run_json;
};

// Runs `scene_text` on native for `duration` with the sound hooks of `vroc run --sound`.
SoundRun runWithSound(const std::string& scene_text, double duration, const std::string& name) {
    if (!BackendRegistry::global().find("native")) native::registerBackend();
    const Scene scene = loadSceneFromString(scene_text, name + ".json");
    const fs::path dir = test::freshDir(name);
    recording::RunRequest request;
    request.scene = &scene;
    request.backend = &BackendRegistry::global().require("native");
    request.settings = resolveSettings(request.backend->settings, {});
    request.frame_dt = scene.frame_dt;
    request.duration = duration;
    request.out_dir = dir / "run";
    std::optional<SoundRecorder> recorder;
    recorder.emplace(scene, scene.frame_dt, duration, dir / "run" / "sound.wav");
    SoundRun out;
    request.on_events = [&](const std::vector<CollisionEvent>& events) { recorder->addEvents(events); };
    request.finish_outputs = [&](recording::RunRecord& record) {
        out.summary = recorder->finish(record.simulated_time);
        record.outputs["sound"] = {out.summary.wav.string(), out.summary.describe()};
    };
    recording::recordRun(request);
    out.events = readEvents(dir / "run" / "events.csv");
    out.wav = readWav(dir / "run" / "sound.wav");
    std::ifstream json(dir / "run" / "run.json");
    out.run_json = nlohmann::json::parse(json);
    fs::remove_all(dir);
    return out;
}

// Both materials ring out within ~5 ms (-80 dB), shorter than the gaps between sounded bounces,
// so every sounded impact starts from silence.
constexpr const char* kBallDrop = R"({"format": "vroc-scene/1", "name": "ball_drop_sound",
  "frame_dt": 0.016666666666666666,
  "materials": {
    "ball": {"restitution": 0.5, "friction": 0.5,
             "sound": {"modes_hz": [1500, 3700], "decay_per_s": [2000, 2500], "gains": [1, 0.5]}},
    "floor": {"restitution": 1.0, "friction": 0.5,
              "sound": {"modes_hz": [400, 900], "decay_per_s": [1500, 1800], "gains": [1, 0.3]}}},
  "bodies": [
    {"name": "floor", "role": "real", "material": "floor", "shape": {"box": {"half_extents": [2, 2, 0.5]}},
     "position": [0, 0, -0.5]},
    {"name": "ball", "role": "virtual", "material": "ball", "mass": 1.0, "shape": {"sphere": {"radius": 0.1}},
     "position": [0, 0, 1.1]}]})";

TEST(ImpactSoundRun, BallDropOnsetsMatchTheRunsEvents) {
    const SoundRun run = runWithSound(kBallDrop, 3.0, "ball-drop");
    ASSERT_EQ(run.wav.sample_rate, 48000);
    ASSERT_EQ(run.wav.channels, 1);
    const double rate = run.wav.sample_rate;
    // Which events should sound, from the stated rule: J >= 2 m |g| dt (1 kg ball) and 10 ms after
    // the pair's previous sounded impact.
    const double threshold = 2 * 1.0 * 9.81 * (1.0 / 60.0);
    std::vector<EventRow> sounded;
    for (const EventRow& e : run.events)
        if (e.impulse >= threshold && (sounded.empty() || e.t - sounded.back().t >= 0.010)) sounded.push_back(e);
    ASSERT_GE(sounded.size(), 4u) << "the e = 0.5 ball bounces audibly at least 4 times";
    EXPECT_EQ(run.summary.sounded, sounded.size());
    EXPECT_EQ(run.summary.sounded + run.summary.quiet + run.summary.refractory, run.events.size());

    const std::vector<std::size_t> onsets =
        test::detectOnsets(run.wav.samples, 1e-3, static_cast<std::size_t>(rate / 500));
    ASSERT_EQ(onsets.size(), sounded.size());
    std::vector<double> peaks;
    for (std::size_t k = 0; k < onsets.size(); ++k) {
        const double event_sample = sounded[k].t * rate;
        EXPECT_GE(static_cast<double>(onsets[k]), event_sample - 1e-6) << "bounce " << k;
        EXPECT_LE(static_cast<double>(onsets[k]) - event_sample, 1.0) << "bounce " << k << " at t = " << sounded[k].t;
        peaks.push_back(test::peakIn(run.wav.samples, onsets[k], static_cast<std::size_t>(rate / 500)));
    }
    // Each bounce has half the impulse of the one before (e = 0.5): quieter in the same order.
    for (std::size_t k = 1; k < sounded.size(); ++k) {
        ASSERT_LT(sounded[k].impulse, sounded[k - 1].impulse);
        EXPECT_LT(peaks[k], peaks[k - 1]) << "bounce " << k;
    }
    EXPECT_NEAR(peaks[0], 0.8912509381337456, 2.0 / 32767) << "normalised to -1 dBFS";
    EXPECT_EQ(run.run_json["outputs"]["sound"]["description"], run.summary.describe());
}

// A 0.2 m box of 1 kg on a floor: at rest on it (gap 0), or dropped from 2 cm.
std::string boxScene(double gap) {
    return std::string(R"({"format": "vroc-scene/1", "name": "box_rest", "frame_dt": 0.016666666666666666,
      "materials": {"m": {"restitution": 0.3, "friction": 0.6}},
      "bodies": [{"name": "floor", "role": "real", "material": "m",
                  "shape": {"box": {"half_extents": [2, 2, 0.5]}}, "position": [0, 0, -0.5]},
                 {"name": "box", "role": "virtual", "material": "m", "mass": 1.0,
                  "shape": {"box": {"half_extents": [0.1, 0.1, 0.1]}}, "position": [0, 0, )") +
           std::to_string(0.1 + gap) + "]}]}";
}

TEST(ImpactSoundRun, RestingBoxIsSilent) {
    const SoundRun run = runWithSound(boxScene(0.0), 1.0, "box-rest");
    EXPECT_EQ(run.summary.sounded, 0u) << run.events.size() << " events";
    const float loudest = *std::max_element(run.wav.samples.begin(), run.wav.samples.end(),
                                            [](float a, float b) { return std::fabs(a) < std::fabs(b); });
    EXPECT_EQ(loudest, 0.0f);
    EXPECT_GE(run.wav.samples.size(), 48000u);
}

TEST(ImpactSoundRun, SettledBoxIsSilentAfterItsLanding) {
    const SoundRun run = runWithSound(boxScene(0.02), 1.0, "box-settle");
    ASSERT_GE(run.summary.sounded, 1u) << "the landing sounds";
    // The landing at t = sqrt(2 * 0.02 / 9.81) = 64 ms and whatever follows it while the box settles
    // ring out; from 0.5 s on the track is silent (below -60 dBFS) while the box rests.
    const double rate = run.wav.sample_rate;
    double after = 0;
    for (std::size_t n = static_cast<std::size_t>(0.5 * rate); n < run.wav.samples.size(); ++n)
        after = std::max(after, static_cast<double>(std::fabs(run.wav.samples[n])));
    EXPECT_LT(after, 1e-3);
    double before = 0;
    for (std::size_t n = 0; n < static_cast<std::size_t>(0.2 * rate); ++n)
        before = std::max(before, static_cast<double>(std::fabs(run.wav.samples[n])));
    EXPECT_GT(before, 0.5);
}

}  // namespace
}  // namespace vroc::audio
