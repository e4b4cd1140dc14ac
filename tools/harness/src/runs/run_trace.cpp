// SPDX-License-Identifier: MIT
#include <algorithm>

#include "vroc/core/body_states.h"
#include "vroc/core/errors.h"
#include "vroc/core/frame_loop.h"
#include "vroc/harness/runs/run_trace.h"

namespace vroc::harness {

double RunTrace::wallTotal() const {
    double sum = 0;
    for (double s : step_wall_s) sum += s;
    return sum;
}

std::vector<BodyState> initialStates(const Scene& scene) {
    std::vector<BodyState> out(scene.bodies.size());
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        const Body& b = scene.bodies[i];
        out[i] = BodyState{b.pose, b.linear_velocity, b.angular_velocity};
    }
    return out;
}

namespace {

bool finiteState(const BodyState& s) {
    return s.pose.position.allFinite() && s.pose.orientation.coeffs().allFinite() &&
           s.linear_velocity.allFinite() && s.angular_velocity.allFinite();
}

void readStates(const Backend& backend, std::vector<BodyState>& out, bool& finite) {
    out.resize(static_cast<std::size_t>(backend.bodyCount()));
    for (int i = 0; i < backend.bodyCount(); ++i) {
        out[static_cast<std::size_t>(i)] = backend.bodyState(i);
        finite = finite && finiteState(out[static_cast<std::size_t>(i)]);
    }
}

}  // namespace

RunTrace runBackend(const BackendInfo& info, const Scene& scene, const Settings& settings,
                    const RunOptions& options) {
    if (!(options.frame_dt > 0)) throw InputError("frame step must be positive");
    std::unique_ptr<Backend> backend = info.create(scene, settings);
    if (options.initial_states) setBodyStates(*backend, scene, *options.initial_states);
    RunTrace trace;
    trace.backend = info.name;
    trace.frame_dt = options.frame_dt;
    const std::size_t keep = options.record_states ? static_cast<std::size_t>(options.frames) + 1 : 2;
    trace.times.reserve(keep);
    trace.states.reserve(keep);
    trace.step_wall_s.reserve(static_cast<std::size_t>(options.frames));

    std::vector<BodyState> states;
    auto record = [&] {
        readStates(*backend, states, trace.finite);
        if (!options.record_states && trace.times.size() == 2) {
            trace.times.pop_back();
            trace.states.pop_back();
            trace.invariants.pop_back();
        }
        trace.times.push_back(backend->time());
        trace.invariants.push_back(computeInvariants(scene, states));
        trace.states.push_back(states);
    };
    record();
    FrameHooks hooks;
    hooks.after_frame = [&](std::int64_t frame, double step_wall_s, std::vector<CollisionEvent>& events) {
        trace.step_wall_s.push_back(step_wall_s);
        trace.events.insert(trace.events.end(), events.begin(), events.end());
        if (frame == options.frames || frame % std::max<std::int64_t>(1, options.record_every) == 0) record();
        if (options.progress) options.progress(frame, options.frames);
        return true;
    };
    stepFrames(*backend, options.frames, options.frame_dt, hooks);
    trace.warnings = backend->warnings();
    trace.statistics = backend->statistics();
    return trace;
}

}  // namespace vroc::harness
