// SPDX-License-Identifier: MIT
#include <chrono>
#include <cmath>

#include "vroc/core/errors.h"
#include "vroc/harness/run_trace.h"

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

std::int64_t framesFor(double duration, double dt) {
    if (!(duration >= 0) || !(dt > 0) || !std::isfinite(duration) || !std::isfinite(dt))
        throw InputError("duration and frame step must be finite, duration >= 0 and step > 0");
    const double n = duration / dt;
    const double nearest = std::round(n);
    if (std::abs(n - nearest) <= 1e-9 * std::max(1.0, n)) return static_cast<std::int64_t>(nearest);
    return static_cast<std::int64_t>(std::ceil(n));
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
    if (options.initial_states) {
        for (std::size_t i = 0; i < scene.bodies.size(); ++i)
            if (!scene.bodies[i].isStatic()) backend->setBodyState(static_cast<int>(i), (*options.initial_states)[i]);
    }
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
    for (std::int64_t f = 0; f < options.frames; ++f) {
        const auto start = std::chrono::steady_clock::now();
        backend->stepFrame(options.frame_dt);
        const auto stop = std::chrono::steady_clock::now();
        trace.step_wall_s.push_back(std::chrono::duration<double>(stop - start).count());
        for (const CollisionEvent& e : backend->takeEvents()) trace.events.push_back(e);
        if (f + 1 == options.frames || (f + 1) % std::max<std::int64_t>(1, options.record_every) == 0) record();
        if (options.progress) options.progress(f + 1, options.frames);
    }
    trace.warnings = backend->warnings();
    trace.statistics = backend->statistics();
    return trace;
}

}  // namespace vroc::harness
