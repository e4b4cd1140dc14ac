// SPDX-License-Identifier: MIT
#include "vroc/audio/sound_recorder.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "vroc/audio/wav_file.h"
#include "vroc/core/csv.h"
#include "vroc/core/errors.h"
#include "vroc/core/recording/atomic_output.h"

namespace vroc::audio {
namespace fs = std::filesystem;

namespace {

constexpr double kTailDecibels = 60.0;   // the track rings out until the slowest mode fell this much

std::vector<ModalModel> materialModels(const Scene& scene) {
    std::vector<ModalModel> models;
    for (const Material& m : scene.materials) models.emplace_back(m.sound, m.name);
    return models;
}

SoundSettings checked(const SoundSettings& settings) {
    validate(settings);
    return settings;
}

}  // namespace

std::string SoundSummary::describe() const {
    return fmt::format("{} Hz mono 16-bit PCM, {:.3f} s; {} impacts sounded, {} quiet, {} refractory; {}", sample_rate,
                       duration, sounded, quiet, refractory, output.describe());
}

fs::path SoundRecorder::eventsCsvPath(const fs::path& wav_path) {
    return wav_path.parent_path() / (wav_path.stem().string() + "_events.csv");
}

SoundRecorder::SoundRecorder(const Scene& scene, double frame_dt, double expected_end_time, fs::path wav_path,
                             const SoundSettings& settings)
    : scene_(scene),
      settings_(checked(settings)),
      wav_path_(std::move(wav_path)),
      gate_(scene, frame_dt, settings_),
      synth_(materialModels(scene), settings_.sample_rate) {
    if (!(expected_end_time <= settings_.max_duration))
        throw InputError(fmt::format("--sound: at most {} s of simulated time can be made into sound (the mix is held "
                                     "in memory), got {} s", settings_.max_duration, expected_end_time));
    checkWritable(wav_path_, "--sound");
    const fs::path csv = eventsCsvPath(wav_path_);
    if (csv == wav_path_)
        throw InputError("--sound '" + wav_path_.string() + "': the WAV cannot be named like its CSV");
    checkWritable(csv, "--sound events file");
}

void SoundRecorder::addEvents(std::span<const CollisionEvent> events) {
    for (const CollisionEvent& e : events) {
        const ImpactStatus status = gate_.classify(e);
        rows_.push_back({e, gate_.threshold(e.body_a, e.body_b), status});
        if (status != ImpactStatus::Sounded) continue;
        if (!std::isfinite(e.time) || e.time < 0)
            throw RunError(fmt::format("collision event at t = {} s cannot be placed in the sound", e.time));
        synth_.add({e.time, e.impulse / settings_.reference_impulse,
                    scene_.bodies[static_cast<std::size_t>(e.body_a)].material,
                    scene_.bodies[static_cast<std::size_t>(e.body_b)].material});
    }
}

SoundSummary SoundRecorder::finish(double end_time) {
    SoundSummary summary;
    summary.wav = wav_path_;
    summary.events_csv = eventsCsvPath(wav_path_);
    summary.sample_rate = settings_.sample_rate;
    double tail = 0;
    double last = end_time;
    for (const Impact& impact : synth_.impacts()) {
        last = std::max(last, impact.time);
        for (int m : {impact.material_a, impact.material_b})
            tail = std::max(tail, synth_.materials()[static_cast<std::size_t>(m)].ringTime(kTailDecibels));
    }
    tail = std::min(tail, settings_.max_tail);
    summary.samples = synth_.onsetSample(last + tail) + 1;
    summary.duration = static_cast<double>(summary.samples) / settings_.sample_rate;
    std::vector<float> samples = synth_.render(summary.samples);
    summary.output = applyOutputStage(samples, settings_);

    std::string text = "t,body_a,body_b,impulse,threshold,sample,status\n";
    for (const Row& row : rows_) {
        csv::appendNumber(text, row.event.time);
        text += ',' + csv::field(scene_.bodies[static_cast<std::size_t>(row.event.body_a)].name) + ',' +
                csv::field(scene_.bodies[static_cast<std::size_t>(row.event.body_b)].name) + ',';
        csv::appendNumber(text, row.event.impulse);
        text += ',';
        csv::appendNumber(text, row.threshold);
        text += ',';
        csv::appendInteger(text, synth_.onsetSample(std::max(0.0, row.event.time)));
        text += ',' + std::string(impactStatusName(row.status)) + '\n';
        if (row.status == ImpactStatus::Sounded) ++summary.sounded;
        if (row.status == ImpactStatus::Quiet) ++summary.quiet;
        if (row.status == ImpactStatus::Refractory) ++summary.refractory;
    }
    // The CSV is renamed into place only once the WAV is: a failed WAV leaves neither.
    recording::AtomicFile events_file(summary.events_csv);
    events_file.write(text);
    writeWav(wav_path_, samples, settings_.sample_rate);
    events_file.commit();
    return summary;
}

}  // namespace vroc::audio
