// SPDX-License-Identifier: MIT
#include "compare_runs.h"

#include "vroc/core/csv.h"
#include "vroc/core/recording/atomic_output.h"
#include "vroc/core/recording/event_writer.h"
#include "vroc/core/recording/trajectory_writer.h"

namespace vroc::harness {

std::vector<std::size_t> anchorFrames(std::size_t frames, int windows, std::int64_t window_frames) {
    std::vector<std::size_t> out;
    if (frames == 0 || windows <= 0) return out;
    const std::int64_t last = static_cast<std::int64_t>(frames) - 1 - window_frames;   // latest start
    if (last < 0) return out;
    for (int k = 0; k < windows; ++k) {
        const auto f = static_cast<std::size_t>(windows == 1 ? 0 : last * k / (windows - 1));
        if (out.empty() || out.back() != f) out.push_back(f);
    }
    return out;
}

std::vector<BodyState> perturbedStates(const Scene& scene, double epsilon) {
    std::vector<BodyState> s = initialStates(scene);
    for (std::size_t i = 0; i < s.size(); ++i)
        if (scene.bodies[i].isDynamic()) s[i].pose.position.x() += epsilon;
    return s;
}

void writeTraceCsv(const Scene& scene, const RunTrace& trace, const std::filesystem::path& dir) {
    std::filesystem::create_directories(dir);
    {
        recording::AtomicFile file(dir / "trajectory.csv");
        recording::TrajectoryWriter writer(file, scene);
        for (std::size_t f = 0; f < trace.states.size(); ++f) writer.writeFrame(trace.times[f], trace.states[f]);
        writer.flush();
        file.commit();
    }
    {
        recording::AtomicFile file(dir / "events.csv");
        recording::EventWriter writer(file, scene);
        writer.write(trace.events);
        writer.flush();
        file.commit();
    }
    recording::AtomicFile file(dir / "step_times.csv");
    std::string text = "step,t_end,wall_us\n";
    for (std::size_t i = 0; i < trace.step_wall_s.size(); ++i) {
        csv::appendInteger(text, i + 1);
        text += ',';
        csv::appendNumber(text, trace.times[i + 1]);
        text += ',';
        csv::appendFixed(text, trace.step_wall_s[i] * 1e6, 6);
        text += '\n';
    }
    file.write(text);
    file.commit();
}

}  // namespace vroc::harness
