// SPDX-License-Identifier: MIT
#include "vroc/viewer/viewer_inputs.h"

#include <algorithm>
#include <cmath>
#include <future>
#include <limits>
#include <map>

#include "body_geometry.h"
#include "engine_tints.h"
#include "ensemble_replay.h"
#include "frame_selection.h"
#include "penetration_flags.h"
#include "run_directory.h"
#include "vroc/core/errors.h"
#include "vroc/core/recording/trajectory_reader.h"
#include "vroc/core/scene_loader.h"

namespace vroc::viewer {
namespace {

namespace fs = std::filesystem;

// One run before frames are selected: every recorded frame.
struct LoadedRun {
    std::string backend, label;
    int member = -1;
    recording::RecordedTrajectory trajectory;
    std::vector<CollisionEvent> events;
};

Scene loadInputScene(const std::vector<RunDirectory>& inputs, const ViewerOptions& options) {
    const std::string file = options.scene_file.empty() ? inputs.front().scene_file : options.scene_file;
    if (!fs::exists(file))
        throw InputError(file + ": the scene recorded by " + inputs.front().dir.string() +
                         " is not there (run vroc view from where the run was made, or pass --scene)");
    Scene scene = loadScene(file);
    if (options.scene_file.empty())
        for (const RunDirectory& in : inputs)
            if (in.scene_sha256 != scene.source_sha256)
                throw InputError(in.dir.string() + ": recorded scene SHA-256 " + in.scene_sha256 + ", but " + file +
                                 " now has " + scene.source_sha256 + " (changed since the run? pass --scene)");
    return scene;
}

std::vector<LoadedRun> loadRuns(const Scene& scene, const std::vector<RunDirectory>& inputs,
                                const ViewerOptions& options, std::vector<std::string>& mismatches) {
    std::vector<LoadedRun> out;
    for (const RunDirectory& in : inputs) {
        for (const RecordedRunFiles& f : in.runs) {
            LoadedRun run{
                f.backend, f.label, -1, recording::readTrajectory(f.trajectory, scene, f.expected_frames), {}};
            if (fs::exists(f.events)) run.events = recording::readEvents(f.events, scene);
            out.push_back(std::move(run));
        }
        if (in.command != "ensemble") continue;
        for (ReplayedMember& m : replayEnsemble(scene, in.ensemble, options.max_members, mismatches))
            out.push_back({m.backend, m.backend + " #" + std::to_string(m.member), m.member, std::move(m.trajectory),
                           std::move(m.events)});
    }
    // The same backend from two directories: tell them apart by directory order.
    std::map<std::string, int> seen;
    for (LoadedRun& r : out)
        if (r.member < 0 && seen[r.label]++ > 0) r.label += " (" + std::to_string(seen[r.label]) + ")";
    return out;
}

// Per backend, the member whose final positions lie closest (sum of distances) to the others'.
void markMedians(std::vector<ViewerRun>& runs) {
    std::map<std::string, std::vector<ViewerRun*>> groups;
    for (ViewerRun& r : runs)
        if (r.member >= 0) groups[r.backend].push_back(&r);
    for (auto& [backend, members] : groups) {
        double best = std::numeric_limits<double>::infinity();
        ViewerRun* median = nullptr;
        for (ViewerRun* a : members) {
            double sum = 0;
            for (const ViewerRun* b : members)
                for (std::size_t k = 0; k < a->poses.back().size(); ++k)
                    sum += (a->poses.back()[k].position - b->poses.back()[k].position).norm();
            if (sum < best) best = sum, median = a;
        }
        for (ViewerRun* m : members) m->median = (m == median);
    }
}

// Every run at the kept frames; all runs must have their frames at the same times.
std::vector<ViewerRun> keptFrames(std::vector<LoadedRun>& loaded, const std::vector<std::size_t>& frames) {
    std::vector<ViewerRun> out;
    const recording::RecordedTrajectory& first = loaded.front().trajectory;
    for (LoadedRun& r : loaded) {
        ViewerRun run{r.backend, r.label, r.member, r.member < 0, {}, {}, std::move(r.events), {}};
        for (std::size_t f : frames) {
            if (std::abs(r.trajectory.times[f] - first.times[f]) > 1e-9 * std::max(1.0, std::abs(first.times[f])))
                throw InputError(r.label + ": frame " + std::to_string(f) +
                                 " is at t = " + std::to_string(r.trajectory.times[f]) + " s, " + loaded.front().label +
                                 "'s at " + std::to_string(first.times[f]) + " s (runs must share one frame step)");
            run.poses.push_back(r.trajectory.poses[f]);
        }
        out.push_back(std::move(run));
    }
    return out;
}

// The costly part of a large scene: one thread per run. Not for the faint ensemble members around
// the median: a glow there would not be seen.
void addPenetration(const Scene& scene, std::vector<ViewerRun>& runs) {
    std::vector<ViewerRun*> judged;
    for (ViewerRun& run : runs)
        if (run.median) judged.push_back(&run);
    std::vector<std::future<std::vector<std::vector<bool>>>> flags;
    for (const ViewerRun* run : judged)
        flags.push_back(std::async(std::launch::async, [&scene, run] { return penetrationFlags(scene, *run); }));
    for (std::size_t i = 0; i < flags.size(); ++i) judged[i]->penetrating = flags[i].get();
}

}  // namespace

ViewerData loadViewerData(const std::vector<fs::path>& dirs, const ViewerOptions& options) {
    if (dirs.empty()) throw InputError("vroc view: no directory given");
    std::vector<RunDirectory> inputs;
    for (const fs::path& d : dirs) inputs.push_back(readRunDirectory(d));
    const Scene scene = loadInputScene(inputs, options);
    std::vector<std::string> mismatches;
    std::vector<LoadedRun> loaded = loadRuns(scene, inputs, options, mismatches);
    if (loaded.empty()) throw InputError(dirs.front().string() + ": no run to show");

    ViewerData data;
    if (!mismatches.empty())
        data.notes.push_back(
            "replayed ensemble members whose final state differs from the recorded one (another "
            "build or backend version?): " +
            mismatches.front() +
            (mismatches.size() > 1 ? " and " + std::to_string(mismatches.size() - 1) + " more" : ""));
    data.title = inputs.size() == 1 ? inputs.front().title : "runs of '" + scene.name + "'";
    data.scene_name = scene.name;
    data.collision_distance = scene.collision_distance;
    data.bodies = viewerBodies(scene);
    data.moving_bodies = loaded.front().trajectory.bodies.size();
    data.recorded_frames = loaded.front().trajectory.frames();
    for (const LoadedRun& r : loaded) data.recorded_frames = std::min(data.recorded_frames, r.trajectory.frames());
    for (const LoadedRun& r : loaded)
        if (r.trajectory.frames() != data.recorded_frames) {
            data.notes.push_back("runs differ in length: all are shown up to the shortest (" +
                                 std::to_string(data.recorded_frames) + " frames)");
            break;
        }
    const FrameSelection sel = selectFrames(data.recorded_frames, data.moving_bodies, loaded.size(), options);
    data.stride = sel.stride;
    for (std::size_t f : sel.frames) data.times.push_back(loaded.front().trajectory.times[f]);
    data.runs = keptFrames(loaded, sel.frames);
    markMedians(data.runs);
    assignEngineTints(data.runs, data.notes);
    if (options.penetration && data.moving_bodies <= options.penetration_max_bodies)
        addPenetration(scene, data.runs);
    else if (options.penetration)
        data.notes.push_back("penetration not highlighted: " + std::to_string(data.moving_bodies) +
                             " moving bodies (more than " + std::to_string(options.penetration_max_bodies) + ")");
    if (sel.stride > 1)
        data.notes.push_back("subsampled: every " + std::to_string(sel.stride) + "th of " +
                             std::to_string(data.recorded_frames) + " recorded frames is shown (" +
                             std::to_string(sel.frames.size()) + " frames), to keep the page small");
    for (const RunDirectory& in : inputs)
        if (in.command == "ensemble" && in.ensemble.members > options.max_members)
            data.notes.push_back(in.dir.string() + ": " + std::to_string(options.max_members) + " of " +
                                 std::to_string(in.ensemble.members) + " members per backend replayed and shown");
    return data;
}

}  // namespace vroc::viewer
