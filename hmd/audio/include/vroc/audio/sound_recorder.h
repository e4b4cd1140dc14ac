// SPDX-License-Identifier: MIT
// The impact sound of one run (`vroc run --sound`, `vroc play --sound`): fed each frame's
// collision events, it writes the WAV and, next to it, "<stem>_events.csv" with every event and
// whether it sounded:
//   t,body_a,body_b,impulse,threshold,sample,status
// t [s], body names, impulse and the pair's quiet threshold [N s], the onset sample index,
// status sounded|quiet|refractory (impact_gate.h).
#pragma once

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "vroc/audio/impact_gate.h"
#include "vroc/audio/impact_synth.h"
#include "vroc/audio/output_stage.h"
#include "vroc/audio/sound_settings.h"
#include "vroc/core/backend.h"
#include "vroc/core/scene.h"

namespace vroc::audio {

struct SoundSummary {
    std::filesystem::path wav;
    std::filesystem::path events_csv;
    std::size_t samples = 0;
    int sample_rate = 0;               ///< [Hz]
    double duration = 0;               ///< [s] of the WAV
    std::size_t sounded = 0, quiet = 0, refractory = 0;
    OutputStageReport output;
    /// One line: format, length, impact counts and the output stage.
    std::string describe() const;
};

class SoundRecorder {
public:
    /// `scene` must outlive the recorder. Checks the settings, the scene's materials and that the
    /// WAV and its CSV can be written, and that `expected_end_time` [s] is at most
    /// settings.max_duration: InputError before any simulation.
    SoundRecorder(const Scene& scene, double frame_dt, double expected_end_time, std::filesystem::path wav_path,
                  const SoundSettings& settings = {});

    /// One frame's events, in time order.
    void addEvents(std::span<const CollisionEvent> events);
    /// Renders [0, end_time + tail) and writes the CSV, then the WAV (each atomically). RunError on
    /// I/O failure (nothing half-written is left).
    SoundSummary finish(double end_time);

    /// Path of the CSV written next to `wav_path`: "<dir>/<stem>_events.csv".
    static std::filesystem::path eventsCsvPath(const std::filesystem::path& wav_path);

private:
    struct Row {
        CollisionEvent event;
        double threshold;
        ImpactStatus status;
    };
    const Scene& scene_;
    SoundSettings settings_;
    std::filesystem::path wav_path_;
    ImpactGate gate_;
    ImpactSynth synth_;
    std::vector<Row> rows_;
};

}  // namespace vroc::audio
