// SPDX-License-Identifier: MIT
#include "vroc/core/recording/run_recorder.h"

#include <charconv>
#include <chrono>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "vroc/core/errors.h"
#include "vroc/core/frame_loop.h"
#include "vroc/core/recording/atomic_output.h"
#include "vroc/core/recording/event_writer.h"
#include "vroc/core/recording/trajectory_writer.h"
#include "vroc/core/state_hash.h"

namespace vroc::recording {
namespace {

using Clock = std::chrono::steady_clock;

// Shortest text that reads back as the same double (messages, not files).
std::string number(double value) {
    char buf[32];
    auto result = std::to_chars(buf, buf + sizeof buf, value);
    return std::string(buf, result.ptr);
}

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// Per-step wall times [µs] with bounded memory: all samples up to kMaxSamples, then a uniform
// systematic sample (every 2nd, 4th, ... step) so percentiles stay representative of the whole
// run; mean and max are exact.
class StepTimeSampler {
public:
    void add(double us) {
        sum_ += us;
        max_ = std::max(max_, us);
        ++count_;
        if (count_ % stride_ != 0) return;
        samples_.push_back(us);
        if (samples_.size() < kMaxSamples) return;
        for (std::size_t i = 0; 2 * i + 1 < samples_.size(); ++i) samples_[i] = samples_[2 * i + 1];
        samples_.resize(samples_.size() / 2);
        stride_ *= 2;
    }
    StepTimes summary() const {
        StepTimes out = summarizeStepTimes(samples_);
        if (count_ > 0) {
            out.mean = sum_ / static_cast<double>(count_);
            out.max = max_;
        }
        return out;
    }

private:
    static constexpr std::size_t kMaxSamples = std::size_t{1} << 22;   // 32 MiB
    std::vector<double> samples_;
    std::uint64_t stride_ = 1;
    std::uint64_t count_ = 0;
    double sum_ = 0;
    double max_ = 0;
};

void readStates(const Backend& backend, std::vector<BodyState>& states) {
    states.resize(static_cast<std::size_t>(backend.bodyCount()));
    for (int i = 0; i < backend.bodyCount(); ++i) states[i] = backend.bodyState(i);
}

void checkRequest(const RunRequest& request) {
    if (!request.scene || !request.backend) throw std::logic_error("recordRun: scene and backend are required");
    frameCount(request.duration, request.frame_dt);   // throws InputError when out of range
    if (request.out_dir.empty()) throw InputError("no output directory given");
}

// Output files of one run, open before the simulation starts so an unwritable place fails early.
struct RunFiles {
    explicit RunFiles(const std::filesystem::path& dir)
        : trajectory(dir / "trajectory.csv"), events(dir / "events.csv"), run_json(dir / "run.json") {}
    AtomicFile trajectory;
    AtomicFile events;
    AtomicFile run_json;
};

// Steps the backend frame by frame, writing every frame; fills timing, counts and final state.
void simulate(const RunRequest& request, Backend& backend, RunFiles& files, RunRecord& record) {
    const Scene& scene = *request.scene;
    TrajectoryWriter trajectory(files.trajectory, scene);
    EventWriter events(files.events, scene);
    std::vector<BodyState> states;
    readStates(backend, states);
    if (states.size() != scene.bodies.size())
        throw RunError("backend '" + request.backend->name + "' reports " + std::to_string(states.size()) +
                       " bodies, the scene has " + std::to_string(scene.bodies.size()));
    trajectory.writeFrame(0.0, states);

    StepTimeSampler step_us;
    FrameHooks hooks;
    hooks.before_frame = request.before_frame;
    hooks.after_frame = [&](std::int64_t frame, double step_wall_s, std::vector<CollisionEvent>& frame_events) {
        step_us.add(step_wall_s * 1e6);
        readStates(backend, states);
        trajectory.writeFrame(backend.time(), states);
        events.write(frame_events);
        if (request.on_events) request.on_events(frame_events);
        if (request.progress && !request.progress(frame, record.steps))
            throw RunError("interrupted at t = " + number(backend.time()) + " s; no run.json written");
        return true;
    };
    stepFrames(backend, record.steps, request.frame_dt, hooks);
    trajectory.flush();
    events.flush();

    record.simulated_time = backend.time();
    record.step_wall_us = step_us.summary();
    record.collision_count = events.count();
    record.pair_count = events.pairCount();
    record.warnings = backend.warnings();
    record.statistics = backend.statistics();
    record.state_hash = hashToHex(stateHash(states));
}

RunRecord initialRecord(const RunRequest& request) {
    RunRecord r;
    const Scene& scene = *request.scene;
    r.scene_name = scene.name;
    r.scene_file = request.scene_file.empty() ? scene.source_path : request.scene_file;
    r.scene_sha256 = scene.source_sha256;
    r.body_count = scene.bodies.size();
    r.virtual_body_count = scene.virtualBodyCount();
    r.backend_name = request.backend->name;
    r.backend_version = request.backend->version;
    r.backend_deviations = request.backend->deviations;
    r.settings = request.settings.values();
    r.frame_dt = request.frame_dt;
    r.duration = request.duration;
    r.steps = frameCount(request.duration, request.frame_dt);
    r.start_time_utc = utcNowIso8601();
    r.build = buildInfo();
    r.command_line = request.command_line;
    return r;
}

}  // namespace

RunRecord recordRun(const RunRequest& request) {
    checkRequest(request);
    const auto wall_start = Clock::now();
    RunRecord record = initialRecord(request);

    const bool created = prepareOutputDirectory(request.out_dir);
    try {
        RunFiles files(request.out_dir);
        std::unique_ptr<Backend> backend = request.backend->create(*request.scene, request.settings);
        if (!backend) throw RunError("backend '" + request.backend->name + "' returned no simulation");
        simulate(request, *backend, files, record);
        files.trajectory.commit();
        files.events.commit();
        if (request.finish_outputs) request.finish_outputs(record);
        record.wall_time_s = secondsSince(wall_start);
        files.run_json.write(toJson(record));
        files.run_json.commit();   // last: from here on the directory is a complete run
    } catch (...) {
        if (created) removeIfEmpty(request.out_dir);
        throw;
    }
    return record;
}

}  // namespace vroc::recording
