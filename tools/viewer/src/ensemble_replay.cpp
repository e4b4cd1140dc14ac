// SPDX-License-Identifier: MIT
#include "ensemble_replay.h"

#include <algorithm>

#include "vroc/core/backend_registry.h"
#include "vroc/core/errors.h"
#include "vroc/core/frame_loop.h"
#include "vroc/core/state_hash.h"
#include "vroc/harness/runs/run_trace.h"

namespace vroc::viewer {
namespace {

recording::RecordedTrajectory movingPoses(const Scene& scene, const harness::RunTrace& trace) {
    recording::RecordedTrajectory out;
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
        if (!scene.bodies[i].isStatic()) out.bodies.push_back(static_cast<int>(i));
    out.times = trace.times;
    for (const std::vector<BodyState>& frame : trace.states) {
        out.poses.emplace_back();
        for (int b : out.bodies) out.poses.back().push_back(frame[static_cast<std::size_t>(b)].pose);
    }
    return out;
}

}  // namespace

std::vector<ReplayedMember> replayEnsemble(const Scene& scene, const EnsembleReplayPlan& plan, int max_members,
                                           std::vector<std::string>& mismatches) {
    std::vector<ReplayedMember> out;
    const int members = std::min(plan.members, max_members);
    for (const EnsembleReplayPlan::Backend& b : plan.backends) {
        const BackendInfo* info = BackendRegistry::global().find(b.name);
        if (!info) throw InputError("ensemble backend '" + b.name + "' is not in this build of vroc");
        for (int m = 0; m < members; ++m) {
            harness::RunOptions ro;
            ro.frame_dt = plan.frame_dt;
            ro.frames = frameCount(plan.duration, plan.frame_dt);
            ro.initial_states = harness::ensembleMemberStates(scene, plan.perturb, plan.seed, m);
            const harness::RunTrace trace = harness::runBackend(*info, scene, Settings(b.settings), ro);
            out.push_back(
                {b.name, m, movingPoses(scene, trace), trace.events, hashToHex(stateHash(trace.states.back()))});
            const auto recorded = plan.recorded_hashes.find({b.name, m});
            if (recorded != plan.recorded_hashes.end() && recorded->second != out.back().state_hash)
                mismatches.push_back(b.name + " #" + std::to_string(m));
        }
    }
    return out;
}

}  // namespace vroc::viewer
