// SPDX-License-Identifier: MIT
// The impact sound from known events (docs/hmd.md#impact-sound): onsets found in the samples by an
// independent detector lie within one sample of the event times, the waveform equals the closed-
// form modal sum, peaks follow the impulses (exactly proportional when nothing limits them), the
// gate silences weak and too-close impacts, and WAV files round-trip and fail cleanly.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <numeric>
#include <sstream>

#include <gtest/gtest.h>

#include "impact_sound_test.h"
#include "vroc/audio/impact_gate.h"
#include "vroc/audio/impact_synth.h"
#include "vroc/audio/output_stage.h"
#include "vroc/audio/sound_recorder.h"
#include "vroc/audio/wav_file.h"
#include "vroc/core/errors.h"
#include "vroc/core/scene_loader.h"

namespace vroc::audio {
namespace {
namespace fs = std::filesystem;
using test::detectOnsets;
using test::peakIn;

constexpr int kRate = 48000;

MaterialSound sound(std::vector<double> f, std::vector<double> d, std::vector<double> g) {
    MaterialSound s;
    s.modes_hz = std::move(f);
    s.decay_per_s = std::move(d);
    s.gains = std::move(g);
    return s;
}

// Two materials that ring out within ~50 ms, so impacts 0.2 s apart are separated by silence.
const MaterialSound kClack = sound({1200, 2900, 5100}, {300, 400, 500}, {1.0, 0.6, 0.3});
const MaterialSound kThud = sound({300, 750}, {200, 260}, {1.0, 0.4});

std::vector<ModalModel> twoModels() { return {ModalModel(kClack, "clack"), ModalModel(kThud, "thud")}; }

// h(tau) of a material straight from its definition (scene.h), not through the library.
double closedForm(const MaterialSound& s, double tau) {
    if (tau < 0) return 0;
    double sum = 0;
    for (std::size_t i = 0; i < s.modes_hz.size(); ++i)
        sum += s.gains[i] * std::exp(-s.decay_per_s[i] * tau) * std::cos(2 * std::numbers::pi * s.modes_hz[i] * tau);
    return sum;
}

TEST(ImpactSynth, OnsetsLieWithinOneSampleOfTheEventTimes) {
    ImpactSynth synth(twoModels(), kRate);
    // Times on and between samples (fractions of a sample period), all material pairings.
    const std::vector<Impact> impacts = {
        {0.0, 0.5, 0, 1},
        {0.25 + 0.3 / kRate, 1.0, 0, 0},
        {0.5 + 0.999 / kRate, 0.1, 1, 1},
        {0.7503, 0.7, 1, 0},
        {1.0 - 1e-9, 0.2, 0, 1},
        {1.2 + 0.5 / kRate, 0.05, 0, 1},
    };
    for (const Impact& i : impacts) synth.add(i);
    const std::vector<float> samples = synth.render(static_cast<std::size_t>(1.5 * kRate));
    // Threshold well below the weakest onset, quiet gap shorter than the spacing of the impacts.
    const std::vector<std::size_t> onsets = detectOnsets(samples, 1e-3 * 0.05, kRate / 50);
    ASSERT_EQ(onsets.size(), impacts.size());
    for (std::size_t k = 0; k < impacts.size(); ++k) {
        const double event_sample = impacts[k].time * kRate;
        EXPECT_GE(static_cast<double>(onsets[k]), event_sample - 1e-6) << "impact " << k << " sounds before it happens";
        EXPECT_LE(static_cast<double>(onsets[k]) - event_sample, 1.0) << "impact " << k;
    }
}

TEST(ImpactSynth, WaveformIsTheClosedFormModalSum) {
    ImpactSynth synth(twoModels(), kRate);
    // Overlapping rings (5 ms apart) and several impacts on one sample.
    const std::vector<Impact> impacts = {{0.01, 1.0, 0, 1}, {0.015 + 0.2 / kRate, 0.4, 0, 0},
                                         {0.015 + 0.2 / kRate, 0.3, 1, 1}, {0.02, 2.0, 1, 0}};
    for (const Impact& i : impacts) synth.add(i);
    const std::size_t count = static_cast<std::size_t>(0.2 * kRate);
    const std::vector<float> samples = synth.render(count);
    const MaterialSound* materials[] = {&kClack, &kThud};
    double worst = 0, peak = 0;
    for (std::size_t n = 0; n < count; ++n) {
        double expected = 0;
        for (const Impact& i : impacts) {
            const double tau = static_cast<double>(n) / kRate - i.time;
            expected += i.amplitude * 0.5 *
                        (closedForm(*materials[i.material_a], tau) + closedForm(*materials[i.material_b], tau));
        }
        worst = std::max(worst, std::fabs(samples[n] - expected));
        peak = std::max(peak, std::fabs(expected));
    }
    EXPECT_GT(peak, 1.0);
    EXPECT_LT(worst, 1e-6 * peak) << "largest difference from the closed form";
}

TEST(ImpactSynth, IsDeterministicAndSilentWithoutImpacts) {
    ImpactSynth a(twoModels(), kRate), b(twoModels(), kRate), none(twoModels(), kRate);
    for (ImpactSynth* s : {&a, &b}) {
        s->add({0.1234567, 0.8, 0, 1});
        s->add({0.1234568, 0.3, 1, 1});
    }
    const std::vector<float> x = a.render(20000), y = b.render(20000), z = none.render(20000);
    EXPECT_EQ(std::memcmp(x.data(), y.data(), x.size() * sizeof(float)), 0);
    EXPECT_TRUE(std::all_of(z.begin(), z.end(), [](float v) { return v == 0.0f; }));
    EXPECT_THROW(a.add({-0.1, 1, 0, 0}), std::invalid_argument);
    EXPECT_THROW(a.add({0.1, 1, 0, 2}), std::invalid_argument);
    EXPECT_THROW(ImpactSynth(twoModels(), 8000), InputError);
}

// A floor and a 0.2 kg ball; the ball's material has no `sound`, so it takes the defaults.
Scene ballScene() {
    return loadSceneFromString(R"({"format": "vroc-scene/1", "name": "sound", "frame_dt": 0.02,
      "materials": {"floor": {"restitution": 1, "friction": 0.5,
                              "sound": {"modes_hz": [300, 750], "decay_per_s": [200, 260], "gains": [1, 0.4]}},
                    "ball": {"restitution": 0.5, "friction": 0.5}},
      "bodies": [{"name": "floor", "role": "real", "material": "floor", "shape": {"box": {"half_extents": [1, 1, 1]}},
                  "position": [0, 0, -1]},
                 {"name": "ball", "role": "virtual", "material": "ball", "mass": 0.2,
                  "shape": {"sphere": {"radius": 0.1}}, "position": [0, 0, 1]}]})",
                               "inline.json");
}

std::vector<CollisionEvent> eventsAt(const std::vector<double>& times, const std::vector<double>& impulses) {
    std::vector<CollisionEvent> events;
    for (std::size_t k = 0; k < times.size(); ++k)
        events.push_back({times[k], 0, 1, Vec3::Zero(), Vec3::UnitZ(), impulses[k]});
    return events;
}

// Peaks of the impacts found in a WAV (first 10 ms after each detected onset).
std::vector<double> impactPeaks(const WavData& wav, std::size_t expected) {
    const std::vector<std::size_t> onsets = detectOnsets(wav.samples, 2.0 / 32767, kRate / 100);
    EXPECT_EQ(onsets.size(), expected);
    std::vector<double> peaks;
    for (std::size_t n : onsets) peaks.push_back(peakIn(wav.samples, n, kRate / 100));
    return peaks;
}

TEST(ImpactSound, PeaksAreOrderedByImpulseAndProportionalWhenUnlimited) {
    const Scene scene = ballScene();
    const fs::path dir = test::freshDir("amplitude");
    // On exact sample times, where each impact's first sample is its peak: a 1/2 (sum g_A + sum g_B).
    const std::vector<double> times = {0.5, 1.0, 1.5, 2.0, 2.5, 3.0};   // 0.5 s: the default modes ring out
    const std::vector<double> impulses = {0.3, 1.2, 0.1, 0.8, 2.0, 0.6};   // all above 2 m |g| dt
    for (const OutputLevel level : {OutputLevel::Normalize, OutputLevel::Fixed}) {
        SoundSettings settings;
        settings.level = level;
        const fs::path wav_path = dir / (std::string(outputLevelName(level)) + ".wav");
        SoundRecorder recorder(scene, scene.frame_dt, 3.5, wav_path, settings);
        recorder.addEvents(eventsAt(times, impulses));
        const SoundSummary summary = recorder.finish(3.5);
        EXPECT_EQ(summary.sounded, impulses.size());
        const WavData wav = readWav(wav_path);
        ASSERT_EQ(wav.sample_rate, kRate);
        ASSERT_EQ(wav.channels, 1);
        const std::vector<double> peaks = impactPeaks(wav, impulses.size());
        ASSERT_EQ(peaks.size(), impulses.size());
        // Same order: sorting the impacts by impulse sorts their peaks.
        std::vector<std::size_t> order(impulses.size());
        std::iota(order.begin(), order.end(), 0);
        std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return impulses[a] < impulses[b]; });
        for (std::size_t k = 1; k < order.size(); ++k)
            EXPECT_LT(peaks[order[k - 1]], peaks[order[k]]) << outputLevelName(level) << ": impulses "
                                                             << impulses[order[k - 1]] << " and " << impulses[order[k]];
        const double gain_sum = 0.5 * ((1 + 0.4) + (1 + 0.5 + 0.25 + 0.125));   // floor and default modes
        if (level == OutputLevel::Normalize) {
            // Proportional, and the loudest at -1 dBFS (16-bit quantisation: 1/32767).
            EXPECT_NEAR(peaks[4], settings.normalize_peak, 1.0 / 32767);
            for (std::size_t k = 0; k < peaks.size(); ++k)
                EXPECT_NEAR(peaks[k], settings.normalize_peak * impulses[k] / impulses[4], 1.0 / 32767) << k;
        } else {
            // Absolute level: J / 1 N s times the gains, exact below the knee, limited (< 1) above.
            for (std::size_t k = 0; k < peaks.size(); ++k) {
                const double linear = impulses[k] * gain_sum;
                if (linear < settings.limiter_knee) {
                    EXPECT_NEAR(peaks[k], linear, 1.0 / 32767) << k;
                } else {
                    EXPECT_LT(peaks[k], std::min(1.0, linear)) << k;
                }
            }
            EXPECT_GT(summary.output.limited, 0u);
        }
    }
    fs::remove_all(dir);
}

TEST(ImpactSound, GateSilencesWeakImpactsAndChatter) {
    const Scene scene = ballScene();
    SoundSettings settings;
    ImpactGate gate(scene, scene.frame_dt, settings);
    const double weight_frame = 2 * 0.2 * 9.81 * 0.02;   // 2 m |g| dt of the ball [N s]
    EXPECT_NEAR(gate.threshold(0, 1), weight_frame, 1e-15);
    const auto at = [](double t, double j) { return CollisionEvent{t, 0, 1, Vec3::Zero(), Vec3::UnitZ(), j}; };
    EXPECT_EQ(gate.classify(at(0.100, 0.99 * weight_frame)), ImpactStatus::Quiet);
    EXPECT_EQ(gate.classify(at(0.101, 0.0)), ImpactStatus::Quiet);
    EXPECT_EQ(gate.classify(at(0.102, 1.01 * weight_frame)), ImpactStatus::Sounded);
    EXPECT_EQ(gate.classify(at(0.102 + 0.0099, 1.0)), ImpactStatus::Refractory);   // 9.9 ms after
    EXPECT_EQ(gate.classify(at(0.102 + 0.0101, 1.0)), ImpactStatus::Sounded);      // 10.1 ms after
    EXPECT_THROW(gate.classify(CollisionEvent{0.2, 0, 5, Vec3::Zero(), Vec3::UnitZ(), 1.0}), RunError);

    // Only the sounded ones reach the WAV; the CSV lists every event with its status.
    const fs::path dir = test::freshDir("gate");
    SoundRecorder recorder(scene, scene.frame_dt, 1.0, dir / "gate.wav", settings);
    recorder.addEvents(eventsAt({0.1, 0.3, 0.305, 0.6}, {0.5 * weight_frame, 0.5, 0.5, 0.2}));
    const SoundSummary summary = recorder.finish(1.0);
    EXPECT_EQ(summary.sounded, 2u);
    EXPECT_EQ(summary.quiet, 1u);
    EXPECT_EQ(summary.refractory, 1u);
    EXPECT_EQ(impactPeaks(readWav(dir / "gate.wav"), 2).size(), 2u);
    std::ifstream csv(dir / "gate_events.csv");
    std::string header, line;
    std::getline(csv, header);
    EXPECT_EQ(header, "t,body_a,body_b,impulse,threshold,sample,status");
    std::vector<std::string> statuses;
    while (std::getline(csv, line)) statuses.push_back(line.substr(line.rfind(',') + 1));
    EXPECT_EQ(statuses, (std::vector<std::string>{"quiet", "sounded", "refractory", "sounded"}));
    fs::remove_all(dir);
}

TEST(OutputStage, LimiterIsMonotonicContinuousAndBelowFullScale) {
    SoundSettings settings;
    settings.level = OutputLevel::Fixed;
    std::vector<float> x;
    for (int i = -4000; i <= 4000; ++i) x.push_back(static_cast<float>(i * 0.001));   // -4 .. 4
    std::vector<float> y = x;
    const OutputStageReport report = applyOutputStage(y, settings);
    // Strictly increasing while float can tell (tanh saturates near 1), never decreasing.
    for (std::size_t i = 1; i < y.size(); ++i) {
        if (std::fabs(x[i]) <= 2.0f) {
            EXPECT_GT(y[i], y[i - 1]) << x[i];
        }
        EXPECT_GE(y[i], y[i - 1]) << x[i];
    }
    for (std::size_t i = 0; i < y.size(); ++i) {
        EXPECT_LT(std::fabs(y[i]), 1.0f);
        if (std::fabs(x[i]) <= 0.5f) {
            EXPECT_EQ(y[i], x[i]);
        }
    }
    EXPECT_EQ(report.limited, 2u * 3500u);   // |x| in (0.5, 4]
    EXPECT_NEAR(report.output_peak, 0.5 + 0.5 * std::tanh(7.0), 1e-6);

    settings.level = OutputLevel::Normalize;
    std::vector<float> z = {0.0f, 3.0f, -6.0f, 1.5f};
    const OutputStageReport norm = applyOutputStage(z, settings);
    EXPECT_NEAR(z[2], -settings.normalize_peak, 1e-7);
    EXPECT_NEAR(z[1], settings.normalize_peak / 2, 1e-7);
    EXPECT_NE(norm.describe().find("normalised"), std::string::npos);
    std::vector<float> silent(10, 0.0f);
    EXPECT_EQ(applyOutputStage(silent, settings).gain, 1.0);
}

TEST(WavFile, RoundTripsWithinOneQuantisationStep) {
    const fs::path dir = test::freshDir("roundtrip");
    std::vector<float> samples;
    for (int n = 0; n < 4800; ++n)
        samples.push_back(
            static_cast<float>(0.5 * std::sin(2 * std::numbers::pi * 1000.0 * n / kRate) + n * 1e-4 - 0.24));
    writeWav(dir / "x.wav", samples, kRate);
    EXPECT_FALSE(fs::exists(dir / "x.wav.tmp"));
    const WavData back = readWav(dir / "x.wav");
    EXPECT_EQ(back.sample_rate, kRate);
    EXPECT_EQ(back.channels, 1);
    ASSERT_EQ(back.samples.size(), samples.size());
    double worst = 0;
    for (std::size_t n = 0; n < samples.size(); ++n)
        worst = std::max(worst, static_cast<double>(std::fabs(back.samples[n] - samples[n])));
    EXPECT_LE(worst, 1.0 / 32767);
    fs::remove_all(dir);
}

TEST(WavFile, FailedWritesSayWhyAndLeaveNothing) {
    const fs::path dir = test::freshDir("fail");
    const std::vector<float> samples(100, 0.25f);
    // No such directory: libsndfile cannot open the temporary file.
    const fs::path missing = dir / "no-such-dir" / "x.wav";
    try {
        writeWav(missing, samples, kRate);
        FAIL() << "expected RunError";
    } catch (const RunError& e) {
        EXPECT_NE(std::string(e.what()).find(missing.string()), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(dir / "no-such-dir"));
    // The final name is a directory: the rename fails after writing; the temporary file goes.
    fs::create_directories(dir / "taken.wav");
    EXPECT_THROW(writeWav(dir / "taken.wav", samples, kRate), RunError);
    EXPECT_TRUE(fs::is_directory(dir / "taken.wav"));
    EXPECT_FALSE(fs::exists(dir / "taken.wav.tmp"));
    // Checked before any work: a directory, or a place that cannot hold files.
    EXPECT_THROW(checkWritable(dir / "taken.wav", "--sound"), InputError);
    EXPECT_THROW(checkWritable("/proc/vroc-no/x.wav", "--sound"), InputError);
    EXPECT_THROW(readWav(dir / "nothing.wav"), InputError);

    // The recorder: a WAV that cannot be written at the end leaves no CSV either.
    const Scene scene = ballScene();
    SoundRecorder recorder(scene, scene.frame_dt, 1.0, dir / "late.wav");
    recorder.addEvents(eventsAt({0.1}, {1.0}));
    fs::create_directories(dir / "late.wav");   // taken after the check
    EXPECT_THROW(recorder.finish(1.0), RunError);
    EXPECT_FALSE(fs::exists(dir / "late_events.csv"));
    EXPECT_FALSE(fs::exists(dir / "late_events.csv.tmp"));
    EXPECT_FALSE(fs::exists(dir / "late.wav.tmp"));
    // Too long a run for the in-memory mix.
    EXPECT_THROW(SoundRecorder(scene, scene.frame_dt, 601.0, dir / "long.wav"), InputError);
    fs::remove_all(dir);
}

TEST(ModalModel, RejectsBadSoundBuiltInCode) {
    EXPECT_NO_THROW(ModalModel(MaterialSound{}, "default"));
    EXPECT_THROW(ModalModel(sound({100, 200}, {10}, {1, 1}), "m"), InputError);
    EXPECT_THROW(ModalModel(sound({}, {}, {}), "m"), InputError);
    EXPECT_THROW(ModalModel(sound({25000}, {10}, {1}), "m"), InputError);
    EXPECT_THROW(ModalModel(sound({100}, {0}, {1}), "m"), InputError);
    EXPECT_THROW(ModalModel(sound({100}, {10}, {-1}), "m"), InputError);
    EXPECT_THROW(ModalModel(sound({std::nan("")}, {10}, {1}), "m"), InputError);
    // -60 dB of the slowest mode: 60 ln(10) / 20 / 40 s.
    EXPECT_NEAR(ModalModel(MaterialSound{}, "default").ringTime(60), 3 * std::log(10.0) / 40, 1e-12);
}

}  // namespace
}  // namespace vroc::audio
